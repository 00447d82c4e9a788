// The runner of the MPI build as a user launches it, `mpirun -np N piezocontact run SCENE`, against the same
// runner on one process: every output field (each VTU array at every output step, each CSV column)
// equal to 1e-10 of its size over the run (see expect_same_results for the one field the serial code
// resolves more coarsely, and relative_tolerance for the time error estimates), the same Newton
// iterations, and the solvers that cannot take a distributed matrix refused or replaced with a reason.
//
// "Its size over the run": a field's largest magnitude in any output step. A field's value near rest
// (the final velocity, 1e-5 of its size during the transient) is a difference of nearly equal numbers,
// which two serial runs by two linear solvers already tell apart at 1e-7 of its own size.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/error_and_temp_dir.hpp"
#include "support/shipped_scenes.hpp"
#include "support/vtu_reader.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kRelativeTolerance = 1e-10;

// The time error estimates (`err_time_*`) are read off a finite difference of the residual with a relative
// step of 1e-7: round-off in the residual (1e-16 of its size) enters them at some 1e-9 of their size in each
// step, and they accumulate over the run. Two runs whose solutions agree to 1e-10 (a factorisation reused
// in one run and fresh in the other, or distributed against serial) give estimates that agree to 1e-7; the
// estimate is an estimate, and its first digits are what a user reads.
constexpr double kEstimateTolerance = 1e-5;

double relative_tolerance(const std::string& field) {
  return field.rfind("column err_time_", 0) == 0 ? kEstimateTolerance : kRelativeTolerance;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Outcome {
  int status = -1;
  std::string log;
};

// The largest difference and the largest magnitude of a field over a run.
struct Spread {
  double difference = 0;
  double size = 0;
};
using Spreads = std::map<std::string, Spread>;

void add(Spreads& spreads, const std::string& field, const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size()) << field;
  Spread& s = spreads[field];
  for (size_t i = 0; i < a.size(); ++i) {
    s.difference = std::max(s.difference, std::abs(a[i] - b[i]));
    s.size = std::max(s.size, std::abs(a[i]));
  }
}

// The field a CSV column holds: ux, uy_corner -> u; vx -> v; phi, phi_center, phi_mean -> phi; the energy
// books' entries (E_..., W_...) -> one field, resolved at the books' scale (the coupling is round-off of
// it); others are their own (coordinates, times, iteration counts: compared at their own size). Empty:
// not compared. E_balance is the work of the residual Newton leaves, which any two valid routes leave
// differently within the tolerance.
std::string field_of_column(const std::string& column) {
  if (column == "E_balance") return "";
  if (column.rfind("E_", 0) == 0 || column.rfind("W_", 0) == 0) return "energy books";
  if (column.rfind("phi", 0) == 0) return "phi";
  if ((column[0] == 'u' || column[0] == 'v') && column.size() >= 2 &&
      std::string("xyz").find(column[1]) != std::string::npos)
    return std::string(1, column[0]);
  return "column " + column;
}

std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(path));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

void compare_csv(const fs::path& a, const fs::path& b, Spreads& spreads) {
  const auto ra = read_csv(a), rb = read_csv(b);
  ASSERT_FALSE(ra.empty()) << a;
  ASSERT_EQ(ra.size(), rb.size()) << a;
  ASSERT_EQ(ra[0], rb[0]) << a;
  for (size_t c = 0; c < ra[0].size(); ++c) {
    std::vector<double> va, vb;
    for (size_t r = 1; r < ra.size(); ++r) {
      va.push_back(std::stod(ra[r][c]));
      vb.push_back(std::stod(rb[r][c]));
    }
    if (const std::string field = field_of_column(ra[0][c]); !field.empty()) add(spreads, field, va, vb);
  }
}

void compare_vtu(const fs::path& a, const fs::path& b, Spreads& spreads) {
  const std::string ta = read_text(a), tb = read_text(b);
  for (const char* section : {"PointData", "CellData"}) {
    const auto names = pc::testing::array_names(ta, section);
    ASSERT_EQ(names, pc::testing::array_names(tb, section)) << a;
    for (const std::string& name : names)
      add(spreads, name, pc::testing::find_array(ta, section, name).doubles(),
          pc::testing::find_array(tb, section, name).doubles());
  }
}

// The arrays of a step written in pieces (a .pvtu), ordered as the points and cells of the same step's
// whole file `whole`: a piece's points are matched by their coordinates, its cells by their points.
void compare_pieces(const std::string& whole, const fs::path& pvtu, Spreads& spreads) {
  using Key = std::array<double, 3>;
  const auto points = pc::testing::find_array(whole, "Points", "Points").doubles();
  std::map<Key, int> point_of;
  for (size_t p = 0; 3 * p < points.size(); ++p)
    point_of[{points[3 * p], points[3 * p + 1], points[3 * p + 2]}] = int(p);
  // A cell by its sorted points.
  const auto cells_of = [](const std::vector<std::int64_t>& connectivity, const std::vector<std::int64_t>& ends,
                           auto&& global) {
    std::vector<std::vector<int>> cells;
    std::int64_t begin = 0;
    for (std::int64_t end : ends) {
      std::vector<int> nodes;
      for (std::int64_t k = begin; k < end; ++k) nodes.push_back(global(int(connectivity[size_t(k)])));
      std::sort(nodes.begin(), nodes.end());
      cells.push_back(nodes);
      begin = end;
    }
    return cells;
  };
  std::map<std::vector<int>, int> cell_of;
  {
    const auto cells = cells_of(pc::testing::find_array(whole, "Cells", "connectivity").int64s(),
                                pc::testing::find_array(whole, "Cells", "offsets").int64s(), [](int p) { return p; });
    for (size_t c = 0; c < cells.size(); ++c) cell_of[cells[c]] = int(c);
  }
  const std::string parallel = read_text(pvtu);
  std::map<std::string, std::vector<double>> gathered;  // "PointData/u" -> values in whole's order
  std::vector<char> point_seen(points.size() / 3, 0), cell_seen(cell_of.size(), 0);
  for (size_t at = parallel.find("<Piece Source=\""); at != std::string::npos;
       at = parallel.find("<Piece Source=\"", at + 1)) {
    const size_t begin = at + 15, end = parallel.find('"', begin);
    const std::string piece = read_text(pvtu.parent_path() / parallel.substr(begin, end - begin));
    const auto piece_points = pc::testing::find_array(piece, "Points", "Points").doubles();
    std::vector<int> global(piece_points.size() / 3);
    for (size_t p = 0; p < global.size(); ++p) {
      const auto found = point_of.find({piece_points[3 * p], piece_points[3 * p + 1], piece_points[3 * p + 2]});
      ASSERT_NE(found, point_of.end()) << pvtu << ": a piece's point is not in the whole file";
      global[p] = found->second;
      point_seen[size_t(found->second)] = 1;
    }
    const auto cells =
        cells_of(pc::testing::find_array(piece, "Cells", "connectivity").int64s(),
                 pc::testing::find_array(piece, "Cells", "offsets").int64s(), [&](int p) { return global[size_t(p)]; });
    std::vector<int> cell_index;
    for (const auto& nodes : cells) {
      const auto found = cell_of.find(nodes);
      ASSERT_NE(found, cell_of.end()) << pvtu << ": a piece's cell is not in the whole file";
      cell_index.push_back(found->second);
      cell_seen[size_t(found->second)] = 1;
    }
    for (const char* section : {"PointData", "CellData"})
      for (const std::string& name : pc::testing::array_names(piece, section)) {
        const pc::testing::DataArray array = pc::testing::find_array(piece, section, name);
        const auto values = array.doubles();
        const bool on_points = std::string(section) == "PointData";
        const size_t entries = on_points ? point_seen.size() : cell_seen.size();
        auto& out = gathered[std::string(section) + "/" + name];
        out.resize(entries * size_t(array.components));
        const std::vector<int>& to = on_points ? global : cell_index;
        for (size_t i = 0; i < to.size(); ++i)
          for (int k = 0; k < array.components; ++k)
            out[size_t(to[i]) * size_t(array.components) + size_t(k)] =
                values[i * size_t(array.components) + size_t(k)];
      }
  }
  EXPECT_EQ(std::count(point_seen.begin(), point_seen.end(), 0), 0) << pvtu << ": points no piece holds";
  EXPECT_EQ(std::count(cell_seen.begin(), cell_seen.end(), 0), 0) << pvtu << ": cells no piece holds";
  for (const char* section : {"PointData", "CellData"})
    for (const std::string& name : pc::testing::array_names(whole, section))
      add(spreads, name, pc::testing::find_array(whole, section, name).doubles(),
          gathered[std::string(section) + "/" + name]);
}

// Every field of runs a and b over the run: their largest difference and a's size.
Spreads compare_runs(const fs::path& a, const fs::path& b) {
  Spreads spreads;
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    const fs::path relative = fs::relative(entry.path(), a);
    const std::string ext = entry.path().extension().string();
    if (ext != ".csv" && ext != ".vtu") continue;
    // A distributed run writes a step as a .pvtu of pieces where a serial one writes a .vtu.
    fs::path parallel = b / relative;
    parallel.replace_extension(".pvtu");
    if (ext == ".vtu" && !fs::exists(b / relative) && fs::exists(parallel)) {
      compare_pieces(read_text(entry.path()), parallel, spreads);
      ++files;
      continue;
    }
    EXPECT_TRUE(fs::exists(b / relative)) << relative << " is missing from " << b;
    if (!fs::exists(b / relative)) continue;
    if (ext == ".csv") compare_csv(entry.path(), b / relative, spreads);
    if (ext == ".vtu") compare_vtu(entry.path(), b / relative, spreads);
    ++files;
  }
  EXPECT_GT(files, 10) << "the runs wrote too few results to compare";
  for (const char* part : {"conductive", "insulated"}) {
    if (!fs::exists(a / part / "summary.json")) continue;
    const std::string sa = read_text(a / part / "summary.json"), sb = read_text(b / part / "summary.json");
    const auto number = [](const std::string& s, const std::string& key) {
      const size_t at = s.find("\"" + key + "\": ");
      return at == std::string::npos ? std::string("missing") : s.substr(at, s.find_first_of(",\n", at) - at);
    };
    EXPECT_EQ(number(sa, "completed"), "\"completed\": true") << part;
    EXPECT_EQ(number(sa, "completed"), number(sb, "completed")) << part;
    // The same Newton method on differently rounded arithmetic (a distributed factorisation): a step whose
    // last residual lands within round-off of the tolerance may take one iteration more or less, no more.
    const auto count = [&](const std::string& s, const std::string& key) {
      const std::string text = number(s, key);
      return text == "missing" ? -1.0 : std::stod(text.substr(key.size() + 4));
    };
    EXPECT_LE(std::abs(count(sa, "newton_iterations_total") - count(sb, "newton_iterations_total")), count(sb, "steps"))
        << part;
  }
  return spreads;
}

// Every result of the distributed run agrees with the serial one to kRelativeTolerance of its size, or, for
// a field that the serial code itself only resolves more coarsely, as closely as two serial runs by two
// linear-solver routes agree (`serial_spread`, with a margin of 4): the conductive contact pressure
// c_nu v_nu, read off a velocity near rest, differs by 4e-8 between the Schur and the full route.
void expect_same_results(const fs::path& serial, const fs::path& distributed, const Spreads& serial_spread) {
  for (const auto& [field, s] : compare_runs(serial, distributed)) {
    const auto other = serial_spread.find(field);
    const double resolution = other == serial_spread.end() ? 0.0 : 4 * other->second.difference;
    EXPECT_LE(s.difference, std::max(relative_tolerance(field) * s.size, resolution))
        << field << ": differs by " << s.difference << ", size " << s.size << " (" << s.difference / s.size
        << " relative; two serial routes differ by " << resolution / 4 << ")";
  }
}

class DistributedRuns : public pc::testing::TemporaryDirectoryTest {
 protected:
  // The runner on `processes` processes (1: without mpirun), with its stdout and stderr in the log.
  Outcome run(int processes, const std::string& arguments) {
    const fs::path log = directory_ / "log.txt";
    std::string command;
    if (processes > 1)
      command = std::string(PIEZOCONTACT_MPIEXEC) + " -np " + std::to_string(processes) + " --oversubscribe ";
    command += std::string(PIEZOCONTACT_RUNNER) + " " + arguments + " >'" + log.string() + "' 2>&1";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(log)};
  }

  void SetUp() override {
    TemporaryDirectoryTest::SetUp();
    // OpenMPI refuses root without these (CI runs as root); they change nothing for other users.
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    setenv("PIEZOCONTACT_THREADS", "1", 1);  // 2 cores: processes, not threads
  }
};

TEST_F(DistributedRuns, PaperSceneOnTwoAndThreeProcessesEqualsOneProcess) {
  const std::string scene = "run " + pc::testing::kPaperScene + " --no-sweep --quiet --out ";
  const fs::path one = directory_ / "one", full = directory_ / "full", two = directory_ / "two",
                 three = directory_ / "three";
  const Outcome serial = run(1, scene + one.string());
  ASSERT_EQ(serial.status, 0) << serial.log;
  const Outcome serial_full = run(1, scene + full.string() + " --set solver.condensed=false");
  ASSERT_EQ(serial_full.status, 0) << serial_full.log;
  const Outcome on_two = run(2, scene + two.string());
  ASSERT_EQ(on_two.status, 0) << on_two.log;
  const Outcome on_three = run(3, scene + three.string());
  ASSERT_EQ(on_three.status, 0) << on_three.log;
  // Each VTU step of a distributed run: a .pvtu and one piece per process.
  for (const char* file : {"paper2d_000200.pvtu", "paper2d_000200_0.vtu", "paper2d_000200_1.vtu"})
    EXPECT_TRUE(fs::exists(two / "conductive" / file)) << file;
  EXPECT_TRUE(fs::exists(three / "conductive" / "paper2d_000200_2.vtu"));
  EXPECT_FALSE(fs::exists(two / "conductive" / "paper2d_000200.vtu"));
  EXPECT_NE(read_text(two / "conductive" / "paper2d.pvd").find("paper2d_000200.pvtu"), std::string::npos);
  const Spreads serial_spread = compare_runs(one, full);
  expect_same_results(one, two, serial_spread);
  expect_same_results(one, three, serial_spread);
}

TEST_F(DistributedRuns, BoxSceneOnTwoProcessesEqualsOneProcess) {
  const std::string scene = "run " + pc::testing::kBoxScene + " --quiet --set time.steps=20 --set time.T=0.08 --out ";
  const fs::path one = directory_ / "one", two = directory_ / "two";
  const Outcome serial = run(1, scene + one.string());
  ASSERT_EQ(serial.status, 0) << serial.log;
  const Outcome on_two = run(2, scene + two.string());
  ASSERT_EQ(on_two.status, 0) << on_two.log;
  expect_same_results(one, two, {});
}

// A distributed run stopped by SIGTERM (a batch system's first signal, which mpirun hands to every process)
// stops on all processes after the same step, with its checkpoint; resumed under mpirun, it ends with the
// results of a run that was never stopped. Two distributed runs agree to round-off, not bit for bit (MUMPS
// sums the processes' entries in the order they arrive).
TEST_F(DistributedRuns, AStoppedRunResumesToTheResultsOfAnUninterruptedOne) {
  const std::string scene = "run " + pc::testing::kPaperScene +
                            " --only insulated --no-sweep --quiet --set time.steps=1500 --set time.T=1.5 "
                            "--set output.checkpoint_every=25 --set output.vtu_every=100 --out ";
  const fs::path whole = directory_ / "whole", stopped = directory_ / "stopped";
  const Outcome reference = run(2, scene + whole.string());
  ASSERT_EQ(reference.status, 0) << reference.log;

  const std::string command = std::string(PIEZOCONTACT_MPIEXEC) + " -np 2 --oversubscribe " + PIEZOCONTACT_RUNNER +
                              " " + scene + stopped.string() + " >'" + (directory_ / "stopped.txt").string() + "' 2>&1";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const fs::path history = stopped / "insulated" / "history.csv";
  for (int i = 0; i < 1200 && (!fs::exists(history) || read_text(history).size() < 300 * 40); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // some 300 steps in
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "mpirun did not exit after SIGTERM";
  ASSERT_EQ(WEXITSTATUS(status), 1) << "the run was not stopped (it ended first?): "
                                    << read_text(directory_ / "stopped.txt");
  EXPECT_NE(read_text(directory_ / "stopped.txt").find("interrupted by SIGTERM"), std::string::npos);
  EXPECT_TRUE(fs::exists(stopped / "insulated" / "checkpoint.bin"));
  const std::string rows = read_text(history);
  const size_t rows_at_stop = std::count(rows.begin(), rows.end(), '\n');
  EXPECT_LT(rows_at_stop, 1500u);

  const Outcome resumed = run(2, scene + stopped.string() + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.log;
  for (const auto& [field, s] : compare_runs(whole, stopped))
    EXPECT_LE(s.difference, relative_tolerance(field) * s.size)
        << field << ": differs by " << s.difference << ", size " << s.size;
  const std::string manifest = read_text(stopped / "manifest.json");
  EXPECT_NE(manifest.find("\"resumes\": 1"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\"state\": \"completed\""), std::string::npos) << manifest;
}

// A condensed path the scene names cannot run distributed: the run says so and factorises J instead.
TEST_F(DistributedRuns, CondensedPathIsReplacedWithAReason) {
  const Outcome o = run(2, "run " + pc::testing::kPaperScene + " --no-sweep --only insulated --set time.steps=4 " +
                               "--set solver.condensation=schur --out " + (directory_ / "out").string());
  ASSERT_EQ(o.status, 0) << o.log;
  EXPECT_NE(o.log.find("distributed over 2 processes: a factorisation of J per iteration"), std::string::npos) << o.log;
  EXPECT_NE(read_text(directory_ / "out" / "insulated" / "summary.json").find("distributed over 2 processes"),
            std::string::npos);
}

// A solver of one process's matrix is refused before any step, naming the key, the value and the fix.
TEST_F(DistributedRuns, ASolverOfOneProcessIsRefused) {
  const Outcome o = run(2, "run " + pc::testing::kPaperScene + " --no-sweep --set solver.linear=umfpack --out " +
                               (directory_ / "out").string());
  EXPECT_NE(o.status, 0);
  EXPECT_NE(o.log.find("solver.linear = 'umfpack' factorises a matrix of one process, but this run is distributed "
                       "over 2 processes; use 'mumps'"),
            std::string::npos)
      << o.log;
}

}  // namespace
