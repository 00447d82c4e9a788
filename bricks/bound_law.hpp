#pragma once
// A brick's law and where its parameters come from. A law that declares parameters (laws/law_parameters.hpp)
// reads them from the model's constants in update(), checked against their declared ranges, so that a
// parameter change is a change of model data that invalidates exactly the bricks reading it (GetFEM: the
// brick stores no data). A law that declares none is held with the fixed values it was built with.
//
// The law lives in a shared object that the brick's kernel points to: update() changes it in place, so the
// term, its pattern and its slot maps survive a parameter change.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assembly/error.hpp"
#include "bricks/brick.hpp"
#include "bricks/laws/law_parameters.hpp"

namespace pc {

// Model constant names of a law's parameters: each parameter's own name ("c_nu"), unless renamed (two
// contact regions with their own coefficients: {{"c_nu", "c_nu_left"}}).
struct ParameterNames {
  std::map<std::string, std::string> renamed;
  std::string operator()(const std::string& parameter) const {
    const auto it = renamed.find(parameter);
    return it == renamed.end() ? parameter : it->second;
  }
};

template <class Law> class BoundLaw {
 public:
  explicit BoundLaw(ParameterNames names) requires DeclaresParameters<Law> : law_(std::make_shared<Law>()),
                                                                             names_(std::move(names)) {}
  explicit BoundLaw(Law fixed) requires(!DeclaresParameters<Law>)
      : law_(std::make_shared<Law>(std::move(fixed))), updated_(true) {}

  // The model constants the law reads (none for a fixed law).
  std::vector<std::string> data() const {
    std::vector<std::string> names;
    if constexpr (DeclaresParameters<Law>)
      for (const auto& p : Law::parameters()) names.push_back(names_(p.name));
    return names;
  }
  // Reads and checks every parameter; messages name the brick, the parameter, the constant and the value.
  void update(const DataView& data, const std::string& brick) {
    if constexpr (DeclaresParameters<Law>) {
      Law law;
      const auto declarations = parameter_declarations<Law>();
      size_t i = 0;
      for (const auto& p : Law::parameters()) {
        const std::string constant = names_(p.name);
        double value = 0;
        try {
          value = data.scalar(constant);
        } catch (const Error& e) {
          fail("brick '", brick, "' reads its parameter ", p.name, " from the model constant '", constant,
               "': ", e.what());
        }
        check_parameter(declarations[i++], value, message("brick '", brick, "' (model constant '", constant, "')"));
        law.*(p.member) = value;
      }
      *law_ = law;
    }
    updated_ = true;
    (void)data, (void)brick;
  }
  // Whether the law holds its parameters: fixed, or read by update() at least once.
  bool updated() const { return updated_; }
  const Law& operator*() const { return *law_; }
  std::shared_ptr<const Law> shared() const { return law_; }

 private:
  std::shared_ptr<Law> law_;
  ParameterNames names_;
  bool updated_ = false;
};

}  // namespace pc
