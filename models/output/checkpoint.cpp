#include "models/output/checkpoint.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>

#include "assembly/atomic_file.hpp"
#include "assembly/content_hash.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

constexpr char magic[8] = {'P', 'C', 'C', 'H', 'K', 'P', 'T', '1'};

// Writes the file's bytes to a stream as they come, hashing them on the way, so that writing a checkpoint
// holds no copy of it in memory (a buffer of the whole file grew to twice its size while the run's
// factors were alive, and was the largest allocation at the run's peak).
class Writer {
 public:
  explicit Writer(std::ostream& out) : out_(out) {}
  void bytes(const char* data, size_t size) {
    if (size == 0) return;
    out_.write(data, std::streamsize(size));
    hash_ = content_hash(std::string_view(data, size), hash_);
  }
  template <class T> void put(const T& value) { bytes(reinterpret_cast<const char*>(&value), sizeof value); }
  void text(const std::string& text) {
    put(std::uint64_t(text.size()));
    bytes(text.data(), text.size());
  }
  // The checksum of everything written, which ends the file.
  void finish() {
    const std::uint64_t sum = hash_;
    out_.write(reinterpret_cast<const char*>(&sum), sizeof sum);
  }

 private:
  std::ostream& out_;
  std::uint64_t hash_ = content_hash({});
};

// Reads the file's bytes in order; every read is bounds-checked, so a truncated file is an error.
class Reader {
 public:
  Reader(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes) {}
  template <class T> T get() {
    T value;
    std::memcpy(&value, take(sizeof value), sizeof value);
    return value;
  }
  std::string text() {
    const std::uint64_t size = get<std::uint64_t>();
    return std::string(take(size), size);
  }
  Eigen::VectorXd vector() {
    const std::uint64_t size = get<std::uint64_t>();
    require(size <= (bytes_.size() - at_) / sizeof(double), "checkpoint '", path_, "' is damaged (a vector of ", size,
            " values overruns the file)");
    Eigen::VectorXd v(static_cast<Eigen::Index>(size));
    const char* values = take(size * sizeof(double));
    if (size > 0) std::memcpy(v.data(), values, size * sizeof(double));  // an empty vector's data() is null
    return v;
  }
  size_t at() const { return at_; }

 private:
  const char* take(std::uint64_t size) {
    require(size <= bytes_.size() - at_, "checkpoint '", path_, "' is truncated or damaged");
    const char* p = bytes_.data() + at_;
    at_ += size;
    return p;
  }
  const std::string& path_;
  std::string_view bytes_;
  size_t at_ = 0;
};

}  // namespace

double Checkpoint::number(const std::string& name) const {
  const auto it = numbers.find(name);
  require(it != numbers.end(), "checkpoint: no number '", name, "'");
  return it->second;
}

const Eigen::VectorXd& Checkpoint::vector(const std::string& name) const {
  const auto it = vectors.find(name);
  require(it != vectors.end(), "checkpoint: no vector '", name, "'");
  return it->second;
}

const std::string& Checkpoint::text(const std::string& name) const {
  const auto it = texts.find(name);
  require(it != texts.end(), "checkpoint: no text '", name, "'");
  return it->second;
}

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint) {
  write_atomically(path, "checkpoint", [&](std::ostream& out) {
    Writer w(out);
    w.bytes(magic, sizeof magic);
    w.put(std::uint64_t(checkpoint.numbers.size()));
    for (const auto& [name, value] : checkpoint.numbers) {
      w.text(name);
      w.put(value);
    }
    w.put(std::uint64_t(checkpoint.vectors.size()));
    for (const auto& [name, values] : checkpoint.vectors) {
      w.text(name);
      w.put(std::uint64_t(values.size()));
      w.bytes(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
    }
    w.put(std::uint64_t(checkpoint.texts.size()));
    for (const auto& [name, text] : checkpoint.texts) {
      w.text(name);
      w.text(text);
    }
    w.finish();
  });
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  require(bool(in), "cannot open the checkpoint '", path, "'");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  require(bytes.size() >= sizeof magic + sizeof(std::uint64_t) && std::memcmp(bytes.data(), magic, sizeof magic) == 0,
          "'", path, "' is not a piezocontact checkpoint");
  const size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + body, sizeof stored);
  require(stored == content_hash(std::string_view(bytes.data(), body)), "checkpoint '", path,
          "' is damaged (its checksum does not match)");

  const std::string_view content(bytes.data(), body);
  Reader r(path, content);
  r.get<std::array<char, sizeof magic>>();
  Checkpoint c;
  for (std::uint64_t n = r.get<std::uint64_t>(); n > 0; --n) {
    std::string name = r.text();
    c.numbers[name] = r.get<double>();
  }
  for (std::uint64_t n = r.get<std::uint64_t>(); n > 0; --n) {
    std::string name = r.text();
    c.vectors[name] = r.vector();
  }
  for (std::uint64_t n = r.get<std::uint64_t>(); n > 0; --n) {
    std::string name = r.text();
    c.texts[name] = r.text();
  }
  require(r.at() == content.size(), "checkpoint '", path, "' is damaged (", content.size() - r.at(),
          " bytes left over)");
  return c;
}

}  // namespace pc
