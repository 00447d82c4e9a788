#pragma once
// A checkpoint: named numbers, vectors and texts in one binary file, enough to continue a run exactly
// where it stopped (see models/model_state.hpp for what a model's state is). Doubles are stored bit for
// bit, so a resumed run repeats the uninterrupted one to the last digit. The file is written atomically
// (never half there) and ends with a checksum, so that a damaged or foreign file is refused, not read.
// Byte order is the machine's: a checkpoint moves between machines of one architecture.
#include <Eigen/Core>
#include <map>
#include <string>

namespace pc {

struct Checkpoint {
  std::map<std::string, double> numbers;
  std::map<std::string, Eigen::VectorXd> vectors;
  std::map<std::string, std::string> texts;

  // Each throws a pc::Error naming the checkpoint and the missing entry.
  double number(const std::string& name) const;
  const Eigen::VectorXd& vector(const std::string& name) const;
  const std::string& text(const std::string& name) const;
};

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);
// Throws a pc::Error naming the file when it cannot be read, is not a checkpoint, or is damaged.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace pc
