#pragma once
// The common shape of the bulk bricks (inertia, viscosity, elasticity, piezoelectric coupling,
// permittivity): one linear term over a cell region, rebuilt from one model constant (a density or a
// material tensor) whenever that constant changes.
#include <memory>
#include <string>

#include <Eigen/Core>

#include "bricks/brick.hpp"

namespace pc {

class MaterialBrick : public Brick {
 public:
  std::string name() const override { return label_ + " (" + datum_ + ") on " + region_; }
  std::vector<std::string> data() const override { return {datum_}; }
  void update(const DataView& data) override { term_ = make_term(data.constant(datum_)); }
  std::vector<BrickTerm> terms() const override;
  bool linear() const override { return true; }
  bool symmetric() const override { return symmetric_; }

 protected:
  MaterialBrick(std::string label, std::string region, std::string datum, bool symmetric)
      : label_(std::move(label)), region_(std::move(region)), datum_(std::move(datum)), symmetric_(symmetric) {}
  const std::string& datum() const { return datum_; }
  // Validates the constant (messages name the datum) and builds the term.
  virtual std::shared_ptr<const Term> make_term(const Eigen::MatrixXd& constant) const = 0;

 private:
  std::string label_, region_, datum_;
  bool symmetric_;
  std::shared_ptr<const Term> term_;
};

}  // namespace pc
