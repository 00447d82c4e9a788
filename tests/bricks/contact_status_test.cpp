// The contact surface at its nodes: each node's normal is its own (the mean of the normals of the faces
// around it), so a curved contact boundary reports the pressure of its own normal at every node.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "assembly/mesh_generators.hpp"
#include "bricks/contact_status.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/testing/brick_checker.hpp"

namespace pc {
namespace {

// A quarter annulus 1 <= r <= 2, 0 <= theta <= pi/2, mapped from the unit square; "inner" is the arc r = 1,
// whose outward normal (out of the body) is -e_r.
std::shared_ptr<const Mesh> quarter_annulus(int n) {
  const Mesh square = rectangle_mesh({0, 0}, {1, 1}, n, n, Shape::Triangle);
  std::vector<double> xy;
  for (int i = 0; i < square.num_nodes(); ++i) {
    const double r = 1 + square.node(i)[1], theta = std::numbers::pi / 2 * (1 - square.node(i)[0]);
    xy.push_back(r * std::cos(theta));
    xy.push_back(r * std::sin(theta));
  }
  auto mesh = std::make_shared<Mesh>(2, Shape::Triangle, xy, square.connectivity());
  mesh->add_boundary_region_where(
      "inner", [](std::span<const double> x) { return std::abs(std::hypot(x[0], x[1]) - 1) < 1e-12; });
  return mesh;
}

TEST(ContactNodes, ACurvedSurfaceIsSplitAlongEachNodesOwnNormal) {
  const int n = 16;
  const auto mesh = quarter_annulus(n);
  const FESpace space(mesh, 1, 2);
  const ContactNodes nodes = contact_nodes(space, "inner");
  ASSERT_EQ(nodes.scalar_dofs.size(), size_t(n + 1));

  // The body moves into the foundation along -e_r at speed s, and slides along e_theta at speed w.
  const double s = 2e-3, w = 5e-3, c_nu = 1e10;
  const Eigen::VectorXd v = space.interpolate([&](const double* x, double* out) {
    const double r = std::hypot(x[0], x[1]);
    out[0] = -s * x[0] / r - w * x[1] / r;
    out[1] = -s * x[1] / r + w * x[0] / r;
  });
  NormalResponseBrick<LinearDampedResponse> normal("inner");
  normal.update(ConstantTable().set("c_nu", c_nu));
  const std::vector<double> pressure = pressure_at_contact_nodes(normal, space, nodes, v, 0.0);
  const std::vector<double> slip = nodal_slip_speed(space, nodes, v, nullptr, 0.0);
  // Interior nodes: the mean of two chords' normals is exactly radial on this uniform arc. The two end
  // nodes have one chord each, whose normal is half a segment, delta = pi / (4 n), off the radius: there
  // v.n = s cos(delta) +- w sin(delta). (The first face's normal would be up to 90 degrees off.)
  const double delta = std::numbers::pi / (4 * n);
  const double end_error = c_nu * (s * (1 - std::cos(delta)) + w * std::sin(delta));
  for (size_t i = 0; i < pressure.size(); ++i) {
    EXPECT_NEAR(pressure[i], c_nu * s, 1.01 * end_error) << "node " << i;
    EXPECT_NEAR(slip[i], w, 0.05 * w) << "node " << i;
  }
  int exact = 0;
  for (double p : pressure) exact += std::abs(p - c_nu * s) < 1e-12 * c_nu * s;
  EXPECT_EQ(exact, n - 1) << "the interior nodes see the exact radial normal";

  const ContactStatus status = contact_status(normal, space, nodes, v, v, 0.5 * w, 0.0);
  EXPECT_EQ(status.nodes, n + 1);
  EXPECT_EQ(status.in_contact, n + 1);
  EXPECT_EQ(status.sliding, n + 1);
  // Lifting off (+e_r) leaves no node in contact.
  const ContactStatus lifted = contact_status(normal, space, nodes, -v, -v, 0.5 * w, 0.0);
  EXPECT_EQ(lifted.in_contact, 0);
}

}  // namespace
}  // namespace pc
