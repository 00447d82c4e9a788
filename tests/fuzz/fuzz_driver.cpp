// The driver that runs a fuzz target (any LLVMFuzzerTestOneInput) without libFuzzer, so that the targets
// build and run with g++: a seeded random-mutation fuzzer over a corpus, a replay of files, and the check
// that malformed inputs are refused with a given message. Deterministic for a seed and an iteration
// count; a run bounded by --seconds stops at a time instead, and prints how many inputs it tried.
//
//   fuzz_<target> [--expect-loaded] FILE|DIR...                  each input once, under the contract
//                                                                (with --expect-loaded, each must load)
//   fuzz_<target> --expect-refusal [--containing TEXT]... FILE   FILE must be refused, naming each TEXT
//   fuzz_<target> --seconds S [--iterations N] [--seed N] [--paths-from JSON] [--timeout S] DIR|FILE...
//
// Mutations stack one to six of: bit flips, byte changes, inserts (random bytes or tokens of the
// dictionary), deletions, duplications, splices with another input, truncations, numbers replaced by
// extreme ones, line deletions, duplications and swaps; on input that parses as JSON, a value replaced by
// a huge, negative, tiny, non-integral or scaled number, a NaN-like string, a value of another type, a
// deep nesting or another value of the document, a member deleted or duplicated, an unknown key added;
// on lines of key=value, paths of the corpus (and --paths-from) with extreme values, and broken paths
// (a..b, a[, a[-1]). There is no coverage feedback: an input whose outcome (loaded, or the refusal's message with its
// numbers and quoted text left out) was not seen before joins the pool that later inputs mutate.
//
// A finding (the target aborts, a sanitizer report, a signal, or an input that runs longer than --timeout
// seconds of CPU time) writes the input to fuzz_<target>-finding.input in the working directory and says
// how to reproduce it.
#include <fcntl.h>
#include <signal.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_support.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define PIEZOCONTACT_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PIEZOCONTACT_FUZZ_ASAN 1
#endif
#endif
#ifdef PIEZOCONTACT_FUZZ_ASAN
#include <sanitizer/common_interface_defs.h>
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using ordered_json = nlohmann::ordered_json;

// ---------------------------------------------------------------------------------------------------------
// The input being run, kept where a signal handler can write it out.

// Never destroyed: the sanitizers' death callback may run after the static destructors (a leak report).
std::string& current_input = *new std::string;
volatile sig_atomic_t running = 0;  // an input is being run: a finding now is that input's
char finding_path[4096] = "fuzz-finding.input";
char reproduce_hint[512] = "";

void write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n <= 0) return;
    data += n;
    size -= std::size_t(n);
  }
}

void write_message(const char* text) { write_all(2, text, std::strlen(text)); }

// Async-signal-safe: open, write, close.
void save_current_input() {
  const int fd = ::open(finding_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    write_all(fd, current_input.data(), current_input.size());
    ::close(fd);
  }
  write_message("fuzz: the input is saved in ");
  write_message(finding_path);
  write_message("\n");
  write_message(reproduce_hint);
}

extern "C" void on_death() {
  if (running) save_current_input();
}

void on_signal(int signal) {
  const bool hang = signal == SIGALRM || signal == SIGPROF;
  write_message(hang ? "fuzz finding: an input ran longer than --timeout (a hang)\n"
                     : "fuzz finding: the target died of a signal\n");
  save_current_input();
  ::signal(signal, SIG_DFL);
  if (hang) ::_exit(1);
  ::raise(signal);
}

// On a stack of its own, so that a stack overflow is reported too. Under AddressSanitizer, which reports
// segmentation faults itself (and then calls on_death), only an abort and the timeout are ours.
void install_handlers() {
  static std::vector<char> stack(1 << 16);
  stack_t alternate{};
  alternate.ss_sp = stack.data();
  alternate.ss_size = stack.size();
  ::sigaltstack(&alternate, nullptr);
  struct sigaction action {};
  action.sa_handler = on_signal;
  action.sa_flags = SA_ONSTACK;
#ifdef PIEZOCONTACT_FUZZ_ASAN
  __sanitizer_set_death_callback(on_death);
  for (int s : {SIGABRT, SIGALRM, SIGPROF}) ::sigaction(s, &action, nullptr);
#else
  for (int s : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGALRM, SIGPROF}) ::sigaction(s, &action, nullptr);
#endif
}

unsigned timeout_seconds = 20;

// The timeout counts CPU time (SIGPROF), so that a loaded machine does not make a slow input a hang;
// five times as much wall time (SIGALRM) catches an input that waits.
void set_timers(unsigned seconds) {
  itimerval cpu{};
  cpu.it_value.tv_sec = seconds;
  ::setitimer(ITIMER_PROF, &cpu, nullptr);
  ::alarm(5 * seconds);
}

int run_one(const std::string& input) {
  current_input = input;
  running = 1;
  set_timers(timeout_seconds);
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  set_timers(0);
  running = 0;
  return 0;
}

// ---------------------------------------------------------------------------------------------------------
// Inputs

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Files, and the files of folders (sorted, so that a seed means the same run everywhere).
std::vector<std::filesystem::path> files_of(const std::vector<std::string>& arguments) {
  std::vector<std::filesystem::path> files;
  for (const std::string& a : arguments) {
    if (std::filesystem::is_directory(a)) {
      std::vector<std::filesystem::path> in_folder;
      for (const auto& entry : std::filesystem::directory_iterator(a))
        if (entry.is_regular_file()) in_folder.push_back(entry.path());
      std::sort(in_folder.begin(), in_folder.end());
      files.insert(files.end(), in_folder.begin(), in_folder.end());
    } else {
      files.emplace_back(a);
    }
  }
  return files;
}

// Every path of a JSON document as --set writes it: "mesh.nx", "material.piezo_E[1][0]".
void collect_paths(const ordered_json& value, const std::string& path, std::vector<std::string>& out) {
  if (!path.empty()) out.push_back(path);
  if (value.is_object()) {
    for (const auto& member : value.items())
      collect_paths(member.value(), path.empty() ? member.key() : path + "." + member.key(), out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) collect_paths(value[i], path + "[" + std::to_string(i) + "]", out);
  }
}

// ---------------------------------------------------------------------------------------------------------
// Mutations

const std::vector<std::string> extreme_values = {"1e400",
                                                 "-1e400",
                                                 "1e-400",
                                                 "1e308",
                                                 "-1e308",
                                                 "1.7976931348623157e308",
                                                 "5e-324",
                                                 "0",
                                                 "-0",
                                                 "-1",
                                                 "-1e9",
                                                 "0.5",
                                                 "-0.5",
                                                 "1e-300",
                                                 "2147483647",
                                                 "2147483648",
                                                 "-2147483649",
                                                 "4294967296",
                                                 "9007199254740993",
                                                 "18446744073709551616",
                                                 "1e9",
                                                 "1e6",
                                                 "100000",
                                                 "nan",
                                                 "NaN",
                                                 "-nan",
                                                 "inf",
                                                 "-inf",
                                                 "Infinity",
                                                 "\"nan\"",
                                                 "\"inf\"",
                                                 "\"\"",
                                                 "\"1e12\"",
                                                 "\"../../escaped\"",
                                                 "\"a\\u0000b\"",
                                                 "\"\\ud800\"",
                                                 "\"\xff\xfe\"",
                                                 "true",
                                                 "false",
                                                 "null",
                                                 "[]",
                                                 "{}",
                                                 "[[]]",
                                                 "[[1]]",
                                                 "[1e308,1e308]",
                                                 "[-1,-1]",
                                                 "[0,0]",
                                                 "[0,0,0]",
                                                 "[0,1e12,3]",
                                                 "{\"type\":\"conductive\"}",
                                                 "\"P2\"",
                                                 "\"box\"",
                                                 "\"rectangle\"",
                                                 "\"quadrilateral\"",
                                                 "\"tetrahedron\"",
                                                 "\"hexahedron\"",
                                                 "2",
                                                 "3",
                                                 "0.0",
                                                 "1"};

const std::vector<std::string> path_breakers = {"..",  ".",   "[",    "]",    "[-1]", "[99999999999999999999]",
                                                "[0]", "[1]", "[+1]", "[ 1]", "[]",   "[0]x",
                                                "=",   "==",  " ",    "\n"};

const std::vector<std::string> json_tokens = {"{",  "}",      "[",        "]",    "\"",          ":", ",",
                                              "\\", "\\u",    "null",     "true", "-",           "e", "E",
                                              ".",  "\"k\":", "{\"\":1}", "\xc3", "\xed\xa0\x80"};

class Mutator {
 public:
  Mutator(std::uint64_t seed, std::vector<std::string> paths) : rng_(seed), paths_(std::move(paths)) {}

  std::size_t below(std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  bool chance(int percent) { return below(100) < std::size_t(percent); }
  template <class T> const T& pick(const std::vector<T>& items) { return items[below(items.size())]; }

  std::string mutate(std::string input, const std::vector<std::string>& pool, std::size_t max_len) {
    const std::size_t count = 1 + below(below(6) + 1);
    for (std::size_t k = 0; k < count; ++k) input = mutate_once(std::move(input), pool);
    if (input.size() > max_len) input.resize(max_len);
    return input;
  }

 private:
  std::string mutate_once(std::string s, const std::vector<std::string>& pool) {
    // Structure first when the input has one: most byte changes only make the parser refuse.
    if (chance(45) && nesting_depth(s) < 300) {
      ordered_json doc = ordered_json::parse(s, nullptr, /*allow_exceptions=*/false);
      if (!doc.is_discarded()) return mutate_json(std::move(doc));
    }
    if (chance(30) && s.find('=') != std::string::npos) return mutate_set_lines(std::move(s));
    return mutate_bytes(std::move(s), pool);
  }

  // nlohmann copies, dumps and walks a document recursively: the driver leaves deeper ones to the bytes.
  static std::size_t nesting_depth(const std::string& s) {
    std::size_t depth = 0, deepest = 0;
    for (char c : s) {
      if (c == '[' || c == '{')
        deepest = std::max(deepest, ++depth);
      else if ((c == ']' || c == '}') && depth > 0)
        --depth;
    }
    return deepest;
  }

  std::string mutate_bytes(std::string s, const std::vector<std::string>& pool) {
    const std::size_t pos = below(s.size() + 1);
    switch (below(11)) {
      case 0:
        if (!s.empty()) s[below(s.size())] ^= char(1 << below(8));
        return s;
      case 1:
        if (!s.empty()) s[below(s.size())] = char(below(256));
        return s;
      case 2: {
        std::string bytes;
        for (std::size_t i = 0, n = 1 + below(8); i < n; ++i) bytes += char(below(256));
        return s.insert(pos, bytes);
      }
      case 3: return s.insert(pos, pick(json_tokens));
      case 4: return s.erase(pos, 1 + below(16));
      case 5: {
        const std::size_t from = below(s.size() + 1);
        return s.insert(pos, s.substr(from, 1 + below(64)));
      }
      case 6: {  // splice: a prefix of this input and a suffix of another
        const std::string& other = pick(pool);
        return s.substr(0, pos) + other.substr(below(other.size() + 1));
      }
      case 7: return s.substr(0, pos);
      case 8: return replace_number(std::move(s));
      case 9: return change_lines(std::move(s));
      default: return s.insert(pos, pick(extreme_values));
    }
  }

  // A number of the text (digits with their sign, point and exponent) replaced by an extreme one.
  std::string replace_number(std::string s) {
    std::vector<std::pair<std::size_t, std::size_t>> numbers;
    for (std::size_t i = 0; i < s.size();) {
      if (std::isdigit(static_cast<unsigned char>(s[i]))) {
        std::size_t start = i > 0 && s[i - 1] == '-' ? i - 1 : i;
        while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || std::strchr(".eE+-", s[i]))) ++i;
        numbers.emplace_back(start, i - start);
      } else {
        ++i;
      }
    }
    if (numbers.empty()) return s;
    const auto [start, length] = pick(numbers);
    return s.replace(start, length, pick(extreme_values));
  }

  std::string change_lines(std::string s) {
    std::vector<std::string> lines;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    if (lines.empty()) return s;
    const std::size_t a = below(lines.size()), b = below(lines.size());
    switch (below(4)) {
      case 0: lines.erase(lines.begin() + std::ptrdiff_t(a)); break;
      case 1: lines.insert(lines.begin() + std::ptrdiff_t(a), lines[b]); break;
      case 2: std::swap(lines[a], lines[b]); break;
      default: lines[a] = replace_number(lines[a]); break;
    }
    std::string out;
    for (const std::string& line : lines) out += line + "\n";
    return out;
  }

  // Lines of key=value: a line replaced by a known path and an extreme value, or its path broken.
  std::string mutate_set_lines(std::string s) {
    std::vector<std::string> lines;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    const std::size_t a = below(lines.size());
    std::string& line = lines[a];
    const std::size_t eq = line.find('=');
    switch (below(4)) {
      case 0:
        if (!paths_.empty()) line = pick(paths_) + "=" + pick(extreme_values);
        break;
      case 1:
        if (!paths_.empty()) lines.push_back(pick(paths_) + "=" + pick(extreme_values));
        break;
      case 2:
        if (eq != std::string::npos) line = line.substr(0, eq + 1) + pick(extreme_values);
        break;
      default: {
        const std::size_t end = eq == std::string::npos ? line.size() : eq;
        line.insert(below(end + 1), pick(path_breakers));
        break;
      }
    }
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
  }

  // Every value of the document, the root included, for picking one to change.
  static void nodes_of(ordered_json& value, std::vector<ordered_json*>& out) {
    out.push_back(&value);
    if (value.is_structured())
      for (auto& child : value) nodes_of(child, out);
  }

  std::string mutate_json(ordered_json doc) {
    std::vector<ordered_json*> nodes;
    nodes_of(doc, nodes);
    ordered_json& node = *pick(nodes);
    const std::string placeholder = "\x01placeholder\x01";
    switch (below(9)) {
      case 8: {  // a number scaled, negated or zeroed: often still valid, so the model gets built
        std::vector<ordered_json*> numbers;
        for (ordered_json* n : nodes)
          if (n->is_number()) numbers.push_back(n);
        if (numbers.empty()) return doc.dump();
        ordered_json& number = *pick(numbers);
        static const std::vector<double> factors = {-1, 0, 0.5, 2, 10, 1e3, 1e-3, 1e100, 1e-100};
        const double scaled = number.get<double>() * pick(factors);
        if (number.is_number_integer() && std::abs(scaled) < 1e15)
          number = static_cast<long long>(scaled);
        else
          number = scaled;
        return doc.dump();
      }
      case 0:
      case 1: {  // an extreme value, written as text: 1e400 and nan are no JSON numbers
        node = placeholder;
        return replace_placeholder(doc.dump(), placeholder, pick(extreme_values));
      }
      case 2: {  // a deep nesting, at the reader's limit (256 levels) and beyond
        static const std::vector<std::size_t> depths = {2, 50, 254, 255, 256, 257, 1000, 100000};
        const std::size_t depth = pick(depths);
        const std::string inner = node.dump();
        node = placeholder;
        return replace_placeholder(doc.dump(), placeholder, std::string(depth, '[') + inner + std::string(depth, ']'));
      }
      case 3: {  // a member or an element deleted
        std::vector<ordered_json*> containers;
        for (ordered_json* n : nodes)
          if (n->is_structured() && !n->empty()) containers.push_back(n);
        if (containers.empty()) return doc.dump();
        ordered_json& c = *pick(containers);
        if (c.is_object())
          c.erase(std::next(c.begin(), std::ptrdiff_t(below(c.size()))).key());
        else
          c.erase(below(c.size()));
        return doc.dump();
      }
      case 4: {  // an unknown key, or a key that is there twice (text level: ordered_json keeps one)
        std::vector<ordered_json*> objects;
        for (ordered_json* n : nodes)
          if (n->is_object()) objects.push_back(n);
        if (objects.empty()) return doc.dump();
        ordered_json& o = *pick(objects);
        if (o.empty() || chance(50)) {
          o["unknown_key_" + std::to_string(below(100))] = 1;
          return doc.dump();
        }
        const auto member = std::next(o.begin(), std::ptrdiff_t(below(o.size())));
        const std::string duplicate = ordered_json(member.key()).dump() + ":" + member.value().dump() + ",";
        const std::string key = member.key();
        o.erase(key);
        o[placeholder] = 0;
        return replace_placeholder(doc.dump(), ordered_json(placeholder).dump() + ":0",
                                   duplicate + ordered_json(key).dump() + ":" + ordered_json(0).dump(), false);
      }
      case 5:  // another value of the document, of another type or shape most likely
        node = ordered_json(*pick(nodes));
        return doc.dump();
      case 6:  // an array grown or emptied
        if (node.is_array() && !node.empty()) {
          if (chance(50))
            node = ordered_json::array();
          else
            for (std::size_t i = 0, n = below(64); i < n; ++i) node.push_back(node[below(node.size())]);
        } else {
          node = ordered_json::array({node, node});
        }
        return doc.dump();
      default: {  // a value of another type
        static const std::vector<ordered_json> others = {
            nullptr, true, "text", ordered_json::array(),         ordered_json::object(),
            -1,      0,    1e300,  ordered_json::array({1, 2, 3})};
        node = pick(others);
        return doc.dump();
      }
    }
  }

  // `quoted` is the placeholder as a JSON string ("..."), unless the caller passed the text to find.
  static std::string replace_placeholder(std::string text, const std::string& placeholder, const std::string& with,
                                         bool quoted = true) {
    const std::string find = quoted ? ordered_json(placeholder).dump() : placeholder;
    const std::size_t at = text.find(find);
    if (at != std::string::npos) text.replace(at, find.size(), with);
    return text;
  }

  std::mt19937_64 rng_;
  std::vector<std::string> paths_;
};

// What an input's outcome looks like with its numbers and quoted names left out: inputs whose outcome
// is new stand for code paths not reached before.
std::string outcome_signature() {
  const pc::fuzz::Outcome& o = pc::fuzz::last_outcome();
  if (!o.refused) return "loaded";
  std::string signature;
  bool quoted = false;
  for (char c : o.message.substr(0, 160)) {
    if (c == '\'')
      quoted = !quoted;
    else if (!quoted && !std::isdigit(static_cast<unsigned char>(c)))
      signature += c;
  }
  return signature;
}

int usage() {
  std::fprintf(stderr,
               "usage: %s [--expect-loaded] FILE|DIR...\n"
               "       %s --expect-refusal [--containing TEXT]... FILE\n"
               "       %s --seconds S [--iterations N] [--seed N] [--max-len BYTES] [--timeout S]\n"
               "          [--paths-from JSON] DIR|FILE...\n",
               "fuzz_<target>", "fuzz_<target>", "fuzz_<target>");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> inputs, containing, paths_from;
  bool expect_refusal = false, expect_loaded = false;
  double seconds = 0;
  std::uint64_t iterations = 0, seed = 1;
  std::size_t max_len = 1 << 16;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) std::exit(usage());
      return argv[++i];
    };
    if (arg == "--expect-refusal")
      expect_refusal = true;
    else if (arg == "--expect-loaded")
      expect_loaded = true;
    else if (arg == "--containing")
      containing.push_back(value());
    else if (arg == "--seconds")
      seconds = std::stod(value());
    else if (arg == "--iterations")
      iterations = std::stoull(value());
    else if (arg == "--seed")
      seed = std::stoull(value());
    else if (arg == "--max-len")
      max_len = std::stoull(value());
    else if (arg == "--timeout")
      timeout_seconds = unsigned(std::stoul(value()));
    else if (arg == "--paths-from")
      paths_from.push_back(value());
    else if (arg.rfind("--", 0) == 0)
      return usage();
    else
      inputs.push_back(arg);
  }
  if (inputs.empty()) return usage();
  const std::string target = std::filesystem::path(argv[0]).filename().string();
  std::snprintf(finding_path, sizeof finding_path, "%s-finding.input", target.c_str());
  install_handlers();
  const std::vector<std::filesystem::path> files = files_of(inputs);

  if (expect_refusal) {
    int failures = 0;
    for (const auto& file : files) {
      run_one(read_file(file));
      const pc::fuzz::Outcome& o = pc::fuzz::last_outcome();
      if (!o.refused) {
        std::printf("FAIL %s: loaded, but it should have been refused\n", file.c_str());
        ++failures;
        continue;
      }
      for (const std::string& text : containing)
        if (o.message.find(text) == std::string::npos) {
          std::printf("FAIL %s: the message does not name '%s':\n%s\n", file.c_str(), text.c_str(), o.message.c_str());
          ++failures;
        }
      std::printf("refused %s:\n%s\n", file.c_str(), o.message.c_str());
    }
    return failures == 0 ? 0 : 1;
  }

  // Replay: every input once (the seeds of a mutation run too).
  std::vector<std::string> pool;
  std::set<std::string> signatures;
  int not_loaded = 0;
  for (const auto& file : files) {
    pool.push_back(read_file(file));
    run_one(pool.back());
    signatures.insert(outcome_signature());
    const pc::fuzz::Outcome& o = pc::fuzz::last_outcome();
    not_loaded += o.refused ? 1 : 0;
    if (seconds <= 0 && iterations == 0)
      std::printf("%s %s%s%s\n", o.refused ? "refused" : "loaded ", file.c_str(), o.refused ? ":\n" : "",
                  o.message.c_str());
  }
  if (expect_loaded && not_loaded > 0) {
    std::printf("FAIL: %d of %zu inputs were refused\n", not_loaded, files.size());
    return 1;
  }
  if (seconds <= 0 && iterations == 0) return 0;
  if (pool.empty()) {
    std::fprintf(stderr, "fuzz: no seed inputs\n");
    return 2;
  }

  std::vector<std::string> paths;
  for (const std::string& seed_text : pool) {
    const ordered_json doc = ordered_json::parse(seed_text, nullptr, false);
    if (!doc.is_discarded()) collect_paths(doc, "", paths);
  }
  for (const std::string& file : paths_from) collect_paths(ordered_json::parse(read_file(file)), "", paths);
  std::sort(paths.begin(), paths.end());
  paths.erase(std::unique(paths.begin(), paths.end()), paths.end());

  Mutator mutator(seed, paths);
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::uint64_t n = 0, refused = 0;
  double slowest = 0;
  const std::size_t max_pool = 2000;
  for (; (iterations == 0 || n < iterations) && (seconds <= 0 || elapsed() < seconds); ++n) {
    std::snprintf(reproduce_hint, sizeof reproduce_hint,
                  "fuzz: reproduce it with: %s --seed %llu --iterations %llu <the same corpus>, or replay the file\n",
                  target.c_str(), static_cast<unsigned long long>(seed), static_cast<unsigned long long>(n + 1));
    // Half of the inputs start from a seed: the pool fills with inputs that are refused early.
    const std::size_t from = mutator.chance(50) ? mutator.below(files.size()) : mutator.below(pool.size());
    const std::string input = mutator.mutate(pool[from], pool, max_len);
    const double before = elapsed();
    run_one(input);
    slowest = std::max(slowest, elapsed() - before);
    refused += pc::fuzz::last_outcome().refused ? 1 : 0;
    if (signatures.insert(outcome_signature()).second && pool.size() < max_pool) pool.push_back(input);
  }
  std::printf(
      "fuzz %s: %llu inputs in %.1f s (seed %llu): %llu refused, %llu loaded, %zu distinct outcomes, "
      "slowest input %.2f s; no finding\n",
      target.c_str(), static_cast<unsigned long long>(n), elapsed(), static_cast<unsigned long long>(seed),
      static_cast<unsigned long long>(refused), static_cast<unsigned long long>(n - refused), signatures.size(),
      slowest);
  return 0;
}
