#pragma once
// Compile-time traits of a constitutive law, read by the bricks templated on it. A law states what it
// knows as `static constexpr bool` members; a trait it does not state takes the cautious default (not
// affine, not dissipative, not monotone, not bounded, not symmetric, reads the velocity and no normal
// pressure), so a user's law only needs its operator().
namespace pc {

// The law's value is affine in its arguments: a brick over it is linear (tangent cached, residual by mat-vec).
template <class Law> inline constexpr bool law_affine = requires { requires Law::affine; };
// p(r) . r >= 0: the law never feeds energy into the body (for foundation laws: monotone in phi).
template <class Law> inline constexpr bool law_dissipative = requires { requires Law::dissipative; };
// A friction law's Jacobian dp/dr is symmetric (p is the gradient of a dissipation potential).
template <class Law> inline constexpr bool law_symmetric = requires { requires Law::symmetric; };
// A friction law that is monotone: (p(a) - p(b)) . (a - b) >= 0 at one pressure, as the gradient of a convex
// dissipation potential is (viscous, regularized Coulomb and Tresca). Velocity-weakening laws (Stribeck)
// are dissipative but not monotone, so this is a claim of its own.
template <class Law> inline constexpr bool law_monotone = requires { requires Law::monotone; };
// A friction law whose force saturates: |p(s r)| tends to a finite limit as s -> infinity (Coulomb, Tresca).
template <class Law> inline constexpr bool law_bounded = requires { requires Law::bounded; };
// A normal law whose argument is the normal displacement u.n rather than the normal velocity v.n.
template <class Law> inline constexpr bool law_uses_displacement = requires { requires Law::uses_displacement; };
// A friction or foundation law that also reads the contact pressure p_nu.
template <class Law> inline constexpr bool law_uses_normal_pressure = requires { requires Law::uses_normal_pressure; };

}  // namespace pc
