#include "models/output/checkpoint.hpp"

#include <cstdint>
#include <array>
#include <cstring>
#include <fstream>
#include <iterator>

#include "assembly/atomic_file.hpp"
#include "assembly/content_hash.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

constexpr char magic[8] = {'P', 'C', 'C', 'H', 'K', 'P', 'T', '1'};

std::uint64_t checksum(const char* data, size_t size) { return content_hash(std::string_view(data, size)); }

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void put_text(std::string& out, const std::string& text) {
  put(out, std::uint64_t(text.size()));
  out += text;
}

// Reads the file's bytes in order; every read is bounds-checked, so a truncated file is an error.
class Reader {
 public:
  Reader(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}
  template <class T>
  T get() {
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
  const std::string& bytes_;
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
  std::string bytes(magic, sizeof magic);
  put(bytes, std::uint64_t(checkpoint.numbers.size()));
  for (const auto& [name, value] : checkpoint.numbers) {
    put_text(bytes, name);
    put(bytes, value);
  }
  put(bytes, std::uint64_t(checkpoint.vectors.size()));
  for (const auto& [name, values] : checkpoint.vectors) {
    put_text(bytes, name);
    put(bytes, std::uint64_t(values.size()));
    if (values.size() > 0) bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  }
  put(bytes, std::uint64_t(checkpoint.texts.size()));
  for (const auto& [name, text] : checkpoint.texts) {
    put_text(bytes, name);
    put_text(bytes, text);
  }
  put(bytes, checksum(bytes.data(), bytes.size()));
  write_atomically(path, "checkpoint", [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); });
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
  require(stored == checksum(bytes.data(), body), "checkpoint '", path, "' is damaged (its checksum does not match)");

  const std::string content = bytes.substr(0, body);
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
  require(r.at() == content.size(), "checkpoint '", path, "' is damaged (", content.size() - r.at(), " bytes left over)");
  return c;
}

}  // namespace pc
