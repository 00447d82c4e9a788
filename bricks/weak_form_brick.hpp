#pragma once
// The generic nonlinear brick: any point-wise flux kernel (see assembly/pointwise_term.hpp) over a region,
// with its tangent derived by Dual. The user states what the engine cannot infer from a kernel: the
// fields it reads, the fields it tests, the tangent blocks it has, and whether it is linear or symmetric
// (by default neither, which is always safe). Tests and couplings are given by field name.
//
//   struct Cubic {  // f0 = k v^3 per component, tested with v
//     double k;
//     template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
//       for (int c = 0; c < in.dim; ++c) out.f0[0][c] = k * in.value[0][c] * in.value[0][c] * in.value[0][c];
//     }
//   };
//   WeakFormBrick brick(WeakForm{.name = "cubic damping", .fields = {{"v"}}, .tests = {"v"},
//                                .couplings = {{"v", "v"}}, .region = "contact", .integration = Integration::Faces},
//                       Cubic{2.0});
#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/pointwise_term.hpp"
#include "bricks/brick.hpp"

namespace pc {

// Every member has a default, so designated initializers may leave any out.
struct WeakForm {
  std::string name{};
  std::vector<FieldUse> fields{};  // the kernel's field index f (value[f], grad[f], f0[f], f1[f]) is the position here
  std::vector<std::string> tests{};
  std::vector<std::pair<std::string, std::string>> couplings{};  // (test, trial)
  std::string region = "all";
  Integration integration = Integration::Cells;
  bool linear = false;
  bool symmetric = false;
  bool time_dependent = false;  // the kernel reads PointInput::time
  int extra_degree = 0;         // quadrature degree beyond 2 * order, for strongly nonlinear kernels
};

template <class Kernel> class WeakFormBrick : public Brick {
 public:
  WeakFormBrick(WeakForm form, Kernel kernel) : form_(std::move(form)) {
    std::vector<int> tests;
    for (const std::string& test : form_.tests) tests.push_back(field_index(test, "test"));
    std::vector<Coupling> couplings;
    for (const auto& [test, trial] : form_.couplings) {
      const int t = field_index(test, "coupling test");
      require(std::find(tests.begin(), tests.end(), t) != tests.end(), "weak form '", form_.name, "': coupling (", test,
              ", ", trial, ") has a test field that is not among its tests");
      couplings.push_back({t, field_index(trial, "coupling trial")});
    }
    term_ = std::make_shared<PointwiseTerm<Kernel>>(form_.name, form_.integration, form_.fields, std::move(tests),
                                                    std::move(couplings), std::move(kernel), form_.extra_degree);
  }

  std::string name() const override { return form_.name; }
  std::vector<BrickTerm> terms() const override { return {{term_, form_.region}}; }
  bool linear() const override { return form_.linear; }
  bool symmetric() const override { return form_.symmetric; }
  bool time_dependent() const override { return form_.time_dependent; }
  const Kernel& kernel() const { return term_->kernel(); }

 private:
  int field_index(const std::string& field, const char* role) const {
    for (int f = 0; f < int(form_.fields.size()); ++f)
      if (form_.fields[f].name == field) return f;
    fail("weak form '", form_.name, "': ", role, " field '", field, "' is not among the fields it reads");
  }

  WeakForm form_;
  std::shared_ptr<const PointwiseTerm<Kernel>> term_;
};

}  // namespace pc
