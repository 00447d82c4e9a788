#pragma once
// What a Model keeps of a linear brick between assemblies (models/model.hpp, "Caching"): whether its
// tangent blocks are those of its current constants, and R0, its residual with every coupled field at
// zero (sources, and terms of uncoupled data fields), with the time and the data fields' versions it was
// assembled at. Its residual is then sum_k K_k x_k + R0, a mat-vec.
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include <Eigen/Core>

namespace pc {

struct LinearBrickCache {
  bool tangent_valid = false;
  bool r0_valid = false;
  double r0_time = 0;
  std::map<std::string, std::uint64_t> r0_data_versions;  // per data field R0 reads
  std::map<std::string, Eigen::VectorXd> r0;              // per test unknown
  std::map<std::string, bool> r0_zero;                    // per test unknown: every entry of r0 is zero

  // The blocks and R0 are assembled again at the next assembly (the brick's constants or terms changed).
  void invalidate();
  // Whether R0 stands: assembled, at `time` for a time-dependent brick, and no data field it reads changed
  // since (`version` gives a field's current version).
  bool r0_current(bool time_dependent, double time,
                  const std::function<std::uint64_t(const std::string&)>& version) const;
  // Drops R0 before it is assembled again.
  void clear_r0();
  // R0 assembled at `time`: summed over the processes (each assembled its elements' share), its zero
  // pieces noted (a piece that is zero everywhere is not added to the residual).
  void finish_r0(double time);
};

}  // namespace pc
