// Output of a run: the VTU/PVD result series and the CSV tables are read back as text; the derived
// piezoelectric fields are checked on linear fields, for which the cell values are exact.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "bricks/voigt.hpp"
#include "models/model.hpp"
#include "models/output/boundary_table.hpp"
#include "models/output/csv_log.hpp"
#include "models/output/piezo_fields.hpp"
#include "models/output/result_series.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/piezo_material.hpp"
#include "support/test_helpers.hpp"
#include "support/vtu_reader.hpp"

namespace pc {
namespace {

namespace fs = std::filesystem;

using testing::read_text;

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> values;
  std::stringstream fields(line);
  for (std::string field; std::getline(fields, field, ',');) values.push_back(std::strtod(field.c_str(), nullptr));
  return values;
}

// (time, file) of every DataSet of a .pvd, in file order; the document must be complete.
std::vector<std::pair<double, std::string>> read_pvd(const fs::path& path) {
  const std::string text = read_text(path);
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << "incomplete collection " << path;
  const std::regex dataset("<DataSet timestep=\"([^\"]+)\"[^>]*file=\"([^\"]+)\"");
  std::vector<std::pair<double, std::string>> steps;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset); it != std::sregex_iterator(); ++it)
    steps.emplace_back(std::strtod((*it)[1].str().c_str(), nullptr), (*it)[2].str());
  return steps;
}

using testing::expect_error_containing;
class OutputTest : public testing::TemporaryDirectoryTest {};

// ---- result series ------------------------------------------------------------------------------

TEST_F(OutputTest, ResultSeriesKeepsAValidCollectionOfExactlyTheWrittenSteps) {
  const Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 2, 2);
  VtuWriter writer(mesh);
  writer.add_cell_data("id", 1, std::vector<double>(mesh.num_cells(), 1.0));
  const fs::path run = directory_ / "nested" / "run";  // created by the series
  ResultSeries series(run.string(), "body");
  EXPECT_TRUE(fs::is_directory(run));
  EXPECT_EQ(series.pvd_path(), (run / "body.pvd").string());

  const std::vector<int> steps = {0, 5, 10, 123456};
  const std::vector<std::string> names = {"body_000000.vtu", "body_000005.vtu", "body_000010.vtu", "body_123456.vtu"};
  const std::vector<double> times = {0.0, 0.1, 0.1 + 0.2, 1.0 / 3.0};
  for (size_t k = 0; k < steps.size(); ++k) {
    EXPECT_EQ(series.write(steps[k], times[k], writer), (run / names[k]).string());
    // After every write the collection lists exactly the steps so far, with their exact times.
    const auto listed = read_pvd(series.pvd_path());
    ASSERT_EQ(listed.size(), k + 1);
    for (size_t j = 0; j <= k; ++j) {
      EXPECT_EQ(listed[j].first, times[j]);
      EXPECT_EQ(listed[j].second, names[j]);
      EXPECT_TRUE(fs::exists(run / names[j]));
    }
  }
  int files = 0;
  for (const auto& entry : fs::directory_iterator(run)) {
    EXPECT_NE(entry.path().extension(), ".tmp");
    ++files;
  }
  EXPECT_EQ(files, int(steps.size()) + 1);
}

TEST_F(OutputTest, ResultSeriesWritesItsFilesInItsFormatAndItsCollectionListsThem) {
  const Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 3, 2);
  std::vector<double> ids(mesh.num_cells());
  for (size_t c = 0; c < ids.size(); ++c) ids[c] = 0.1 * double(c);
  VtuWriter writer(mesh);
  writer.add_cell_data("id", 1, ids);
  const std::map<VtuFormat, std::string> encoding = {{VtuFormat::Ascii, "ascii"},
                                                     {VtuFormat::Base64, "binary"},
                                                     {VtuFormat::Binary, "appended"},
                                                     {VtuFormat::Zlib, "appended"}};
  for (const auto& [format, array_format] : encoding) {
    SCOPED_TRACE(to_string(format));
    const fs::path run = directory_ / to_string(format);
    ResultSeries series(run.string(), "body", format);
    series.write(0, 0.0, writer);
    series.write(7, 0.5, writer);
    const auto listed = read_pvd(series.pvd_path());
    ASSERT_EQ(listed.size(), 2u);
    for (const auto& [time, file] : listed) {
      ASSERT_TRUE(fs::exists(run / file)) << file;
      const std::string vtu = read_text(run / file);
      const testing::DataArray array = testing::find_array(vtu, "CellData", "id");
      EXPECT_EQ(array.format, array_format) << file;
      EXPECT_EQ(array.doubles(), ids) << file;
      EXPECT_EQ(testing::element_attribute(vtu, "VTKFile", "compressor"),
                format == VtuFormat::Zlib ? "vtkZLibDataCompressor" : "");
    }
    EXPECT_EQ(listed[1].second, "body_000007.vtu");
  }
}

TEST_F(OutputTest, ResultSeriesRewritingAStepReplacesItsTime) {
  const Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 1, 1);
  const VtuWriter writer(mesh);
  ResultSeries series(directory_.string(), "body");
  series.write(0, 0.0, writer);
  series.write(1, 0.5, writer);
  series.write(1, 0.25, writer);
  const auto listed = read_pvd(series.pvd_path());
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[1].first, 0.25);
}

TEST_F(OutputTest, ResultSeriesRefusesBadArgumentsNamingThePath) {
  std::ofstream(directory_ / "blocker") << "a file where a directory should go";
  const std::string impossible = (directory_ / "blocker" / "run").string();
  expect_error_containing([&] { ResultSeries(impossible, "body"); }, {impossible});

  const Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 1, 1);
  const VtuWriter writer(mesh);
  ResultSeries series(directory_.string(), "body");
  expect_error_containing([&] { series.write(-1, 0.0, writer); }, {"body.pvd", "-1"});
  expect_error_containing([&] { series.write(0, std::nan(""), writer); }, {"body.pvd", "not finite"});
}

// ---- CSV ----------------------------------------------------------------------------------------

TEST_F(OutputTest, CsvLogRowsAreOnDiskAtOnceAndReadBackExactly) {
  const fs::path path = directory_ / "log.csv";
  std::ofstream(path) << "stale content\nfrom an earlier run\n";
  CsvLog log(path.string(), {"t", "value", "ratio"});
  const std::vector<std::vector<double>> rows = {
      {0.0, 0.1 + 0.2, 1.0 / 3.0}, {1e-300, -2.5e17, std::sqrt(2.0)}, {3.0, 4.0, 5.0}};
  for (size_t k = 0; k < rows.size(); ++k) {
    log.row(rows[k]);
    // Read while the log is still open: every finished row is already in the file.
    const auto lines = read_lines(path);
    ASSERT_EQ(lines.size(), k + 2);
    EXPECT_EQ(lines[0], "t,value,ratio");
    for (size_t j = 0; j <= k; ++j) EXPECT_EQ(parse_row(lines[j + 1]), rows[j]);
  }
  EXPECT_EQ(log.rows_written(), 3);
  EXPECT_EQ(parse_row(read_lines(path)[1])[1], 0.1 + 0.2);
  EXPECT_NE(parse_row(read_lines(path)[1])[1], 0.3);
}

TEST_F(OutputTest, CsvLogWrongValueCountThrowsNamingFileAndCounts) {
  const std::string path = (directory_ / "log.csv").string();
  CsvLog log(path, {"a", "b"});
  log.row({1, 2});
  expect_error_containing([&] { log.row({1, 2, 3}); }, {path, "3 values", "2 columns"});
  expect_error_containing([&] { log.row({}); }, {path, "0 values", "2 columns"});
  EXPECT_EQ(read_lines(path).size(), 2u);  // the header and the one good row
  EXPECT_EQ(log.rows_written(), 1);
}

// A resumed run continues its history after the checkpoint's rows: later rows (computed after the
// checkpoint by the run that was killed) are cut off, and a file of other columns is refused.
// A series continued from nothing (a fresh run into a used folder) removes its own earlier step files
// only: another series' files, whose name starts alike, and other files stay.
TEST_F(OutputTest, AContinuedSeriesRemovesOnlyItsOwnStaleStepFiles) {
  for (const char* name : {"s_000003.vtu", "s_000010.vtu", "s_fine_000000.vtu", "s_notes.vtu", "s.pvd.bak"})
    std::ofstream(directory_ / name) << "x";
  ResultSeries series(directory_.string(), "s");
  series.continue_from({});
  EXPECT_FALSE(fs::exists(directory_ / "s_000003.vtu"));
  EXPECT_FALSE(fs::exists(directory_ / "s_000010.vtu"));
  EXPECT_TRUE(fs::exists(directory_ / "s_fine_000000.vtu"));
  EXPECT_TRUE(fs::exists(directory_ / "s_notes.vtu"));
  EXPECT_TRUE(fs::exists(directory_ / "s.pvd.bak"));
  EXPECT_TRUE(series.written().empty());
  expect_error_containing([&] { series.continue_from({{4, 0.5}}); }, {"the file of step 4", "is missing"});
}

// A distributed run's series: a step's .pvtu and its pieces are the series' files; continued (resumed,
// perhaps on another number of processes), a kept step keeps the file it was written as and its pieces,
// and the other steps' files of both kinds go.
TEST_F(OutputTest, AContinuedSeriesKeepsItsStepsPiecesAndClearsTheOthers) {
  for (const char* name : {"s_000000.pvtu", "s_000000_0.vtu", "s_000000_1.vtu", "s_000005.vtu", "s_000010.pvtu",
                           "s_000010_0.vtu", "s_000010_1.vtu", "s_000010_.vtu", "s_000010_x.vtu"})
    std::ofstream(directory_ / name) << "x";
  for (const char* name : {"s_000000.pvtu", "s_000000_0.vtu", "s_000000_12.vtu", "s_000005.vtu"})
    EXPECT_TRUE(ResultSeries::is_step_file("s", name)) << name;
  for (const char* name : {"s_000010_.vtu", "s_000010_x.vtu", "s_.pvtu", "s_000010.pvtu.tmp"})
    EXPECT_FALSE(ResultSeries::is_step_file("s", name)) << name;
  ResultSeries series(directory_.string(), "s");
  series.continue_from({{0, 0.0}, {5, 0.5}});
  for (const char* kept :
       {"s_000000.pvtu", "s_000000_0.vtu", "s_000000_1.vtu", "s_000005.vtu", "s_000010_.vtu", "s_000010_x.vtu"})
    EXPECT_TRUE(fs::exists(directory_ / kept)) << kept;
  for (const char* gone : {"s_000010.pvtu", "s_000010_0.vtu", "s_000010_1.vtu"})
    EXPECT_FALSE(fs::exists(directory_ / gone)) << gone;
  const std::string pvd = read_text(directory_ / "s.pvd");
  EXPECT_NE(pvd.find("file=\"s_000000.pvtu\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("file=\"s_000005.vtu\""), std::string::npos) << pvd;
}

TEST_F(OutputTest, CsvLogContinuesAfterTheRowsKept) {
  const std::string path = (directory_ / "log.csv").string();
  {
    CsvLog log(path, {"t", "x"});
    for (int k = 0; k < 5; ++k) log.row({double(k), 10.0 * k});
  }
  std::ofstream(path, std::ios::app) << "5,5";  // a row cut short by a kill
  {
    CsvLog log = CsvLog::continue_after(path, {"t", "x"}, 3);
    EXPECT_EQ(log.rows_written(), 3);
    log.row({3.5, 35});
  }
  const auto lines = read_lines(path);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[3], "2,20");
  EXPECT_EQ(lines[4], "3.5,35");
  expect_error_containing([&] { CsvLog::continue_after(path, {"t", "y"}, 1); }, {path, "its header is 't,x'"});
  expect_error_containing([&] { CsvLog::continue_after(path, {"t", "x"}, 9); }, {path, "only 4 complete rows"});
}

// A full disk: a row that does not fit is cut off again, so the file ends with a whole row. The file-size
// limit (RLIMIT_FSIZE, with SIGXFSZ ignored) makes the write fail part-way, as a full disk does.
TEST_F(OutputTest, ARowThatCannotBeWrittenWholeIsCutOff) {
  const std::string path = (directory_ / "log.csv").string();
  CsvLog log(path, {"t", "value"});
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = saved;
  limited.rlim_cur = 100;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  std::string error;
  int rows = 0;
  try {
    for (; rows < 100; ++rows) log.row({1.0 / 3.0, 2.0 / 3.0});
  } catch (const Error& e) {
    error = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(error.find("disk full"), std::string::npos) << error;
  EXPECT_NE(error.find(std::to_string(rows) + " complete rows"), std::string::npos) << error;
  const std::string text = read_text(path);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "a half-written row";
  EXPECT_EQ(read_lines(path).size(), size_t(rows) + 1);
  EXPECT_LE(text.size(), 100u);
}

TEST_F(OutputTest, CsvColumnNamesMustBePlain) {
  const std::string path = (directory_ / "log.csv").string();
  expect_error_containing([&] { CsvLog(path, {"a", "b,c"}); }, {path, "b,c"});
  expect_error_containing([&] { CsvLog(path, {}); }, {path, "no columns"});
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(OutputTest, WriteCsvWritesTheWholeTableAtomically) {
  const fs::path path = directory_ / "table.csv";
  write_csv(path.string(), {"x", "y"}, {{0.1, 0.2}, {0.1 + 0.2, -1}});
  const auto lines = read_lines(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "x,y");
  EXPECT_EQ(parse_row(lines[2]), (std::vector<double>{0.1 + 0.2, -1}));
  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));

  // A bad table leaves the previous file as it was.
  expect_error_containing(
      [&] {
        write_csv(path.string(), {"x", "y"}, {{1, 2}, {3}});
      },
      {path.string(), "1 values", "2 columns"});
  EXPECT_EQ(read_lines(path), lines);
  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
}

// ---- derived piezoelectric fields ---------------------------------------------------------------

// Linear fields: u = G x + u0, v = H x, phi = p . x + 1, so that every cell value is known exactly.
struct LinearFields {
  Eigen::MatrixXd G, H;
  Eigen::VectorXd p;
};

LinearFields fields_2d() {
  LinearFields f;
  f.G.resize(2, 2);
  f.G << 0.3, -0.2, 0.5, 0.1;
  f.H.resize(2, 2);
  f.H << -1.0, 0.4, 0.0, 2.0;
  f.p.resize(2);
  f.p << 0.7, -1.3;
  return f;
}

Eigen::VectorXd interpolate_affine(const FESpace& space, const Eigen::MatrixXd& M, double offset) {
  const int dim = space.mesh().dim();
  return space.interpolate([&](const double* x, double* out) {
    for (int i = 0; i < M.rows(); ++i) {
      out[i] = offset;
      for (int j = 0; j < dim; ++j) out[i] += M(i, j) * x[j];
    }
  });
}

// An unfinalized model only holding fields: "v" and (optionally) "phi" unknowns, the history "u_prev"
// and the affine "u" = 0 * v + 1 * u_prev, as a time scheme sets it.
std::unique_ptr<Model> linear_model(std::shared_ptr<const Mesh> mesh, int order, const LinearFields& f,
                                    bool with_potential) {
  auto model = std::make_unique<Model>(mesh);
  const int dim = mesh->dim();
  auto vectors = std::make_shared<FESpace>(mesh, order, dim);
  model->add_unknown("v", vectors);
  model->set_values("v", interpolate_affine(*vectors, f.H, 0.0));
  model->add_data_field("u_prev", vectors, interpolate_affine(*vectors, f.G, 0.25));
  model->add_affine_field("u", "v", {"u_prev"});
  model->set_affine("u", 0.0, {1.0});
  if (with_potential) {
    auto scalars = std::make_shared<FESpace>(mesh, order, 1);
    model->add_unknown("phi", scalars);
    model->set_values("phi", interpolate_affine(*scalars, f.p.transpose(), 1.0));
  }
  return model;
}

Eigen::VectorXd voigt_strain(const Eigen::MatrixXd& gradient) {
  const int dim = int(gradient.rows());
  Eigen::VectorXd eps(voigt_size(dim));
  strain_from_gradient(dim, Eigen::MatrixXd(gradient.transpose()).data(), eps.data());  // row-major gradient
  return eps;
}

void expect_cells_equal(const std::vector<double>& values, const Eigen::VectorXd& expected, int num_cells,
                        const char* what) {
  ASSERT_EQ(values.size(), size_t(num_cells) * expected.size()) << what;
  for (int c = 0; c < num_cells; ++c)
    for (int k = 0; k < expected.size(); ++k)
      EXPECT_NEAR(values[size_t(c) * expected.size() + k], expected[k], 1e-12)
          << what << " cell " << c << " entry " << k;
}

testing::PiezoTensors material_2d() {
  testing::PiezoTensors m;
  m.A = 0.1 * isotropic_stiffness(2, 2.0, 1.0);
  m.B = isotropic_stiffness(2, 3.0, 2.0);
  m.E.resize(2, 3);
  m.E << 0.0, 0.0, 0.7, -0.3, 1.1, 0.0;
  m.beta.resize(2, 2);
  m.beta << 2.0, 0.1, 0.1, 3.0;
  return m;
}

// The tensors as the model's constants, where the output reads them.
void set_constants(Model& model, const testing::PiezoTensors& m) {
  model.set_constant("A", m.A);
  model.set_constant("B", m.B);
  model.set_constant("E", m.E);
  model.set_constant("beta", m.beta);
}

TEST(PiezoFields, LinearFieldsGiveExactCellValuesOnEveryShapeAndOrder) {
  const LinearFields f = fields_2d();
  const testing::PiezoTensors m = material_2d();
  const Eigen::VectorXd eps_u = voigt_strain(f.G);
  const Eigen::VectorXd eps_v = voigt_strain(f.H);
  for (Shape shape : {Shape::Triangle, Shape::Quadrilateral})
    for (int order : {1, 2}) {
      SCOPED_TRACE(message(to_string(shape), " order ", order));
      auto mesh = std::make_shared<const Mesh>(rectangle_mesh({-1, 0}, {2, 1.5}, 4, 3, shape));
      const auto model = linear_model(mesh, order, f, true);
      set_constants(*model, m);
      const int cells = mesh->num_cells();
      expect_cells_equal(cell_strain(*model, "u"), eps_u, cells, "strain");
      expect_cells_equal(cell_stress(*model), m.A * eps_v + m.B * eps_u + m.E.transpose() * f.p, cells, "stress");
      expect_cells_equal(cell_electric_field(*model, "phi"), -f.p, cells, "electric field");
      expect_cells_equal(cell_electric_displacement(*model), m.E * eps_u - m.beta * f.p, cells,
                         "electric displacement");
    }
}

TEST(PiezoFields, MechanicalModelStressIsElasticStress) {
  const LinearFields f = fields_2d();
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 3, 2));
  const auto model = linear_model(mesh, 1, f, false);
  const testing::PiezoTensors m = material_2d();
  // No "A": no viscosity. Without a potential, "beta" is not needed and "E" only for D = E eps(u).
  model->set_constant("B", m.B);
  model->set_constant("E", m.E);
  expect_cells_equal(cell_stress(*model), m.B * voigt_strain(f.G), mesh->num_cells(), "stress");
  expect_cells_equal(cell_electric_displacement(*model), m.E * voigt_strain(f.G), mesh->num_cells(), "D");
}

TEST_F(OutputTest, AConstantChangedInTheModelShowsInTheWrittenStress) {
  const LinearFields f = fields_2d();
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 3, 2));
  const auto model = linear_model(mesh, 1, f, false);
  const Eigen::MatrixXd B = material_2d().B;
  model->set_constant("B", B);
  const auto written = [&](const std::string& file, const std::string& name) {
    VtuWriter writer(*mesh);
    add_piezo_output(writer, *model);
    writer.write((directory_ / file).string());
    return testing::find_array(read_text(directory_ / file), "CellData", name).doubles();
  };
  const std::vector<double> stress = written("before.vtu", "stress");
  const std::vector<double> equivalent = written("before.vtu", "von_mises");
  expect_cells_equal(stress, B * voigt_strain(f.G), mesh->num_cells(), "stress before");

  // Without a viscosity or a potential, the stress is B eps(u): it scales with B, and so does von Mises.
  model->set_constant("B", 2.5 * B);
  const std::vector<double> scaled = written("after.vtu", "stress");
  const std::vector<double> scaled_equivalent = written("after.vtu", "von_mises");
  ASSERT_EQ(scaled.size(), stress.size());
  for (size_t k = 0; k < stress.size(); ++k) EXPECT_NEAR(scaled[k], 2.5 * stress[k], 1e-12) << "entry " << k;
  ASSERT_EQ(scaled_equivalent.size(), equivalent.size());
  for (size_t c = 0; c < equivalent.size(); ++c)
    EXPECT_NEAR(scaled_equivalent[c], 2.5 * equivalent[c], 1e-12) << "cell " << c;
}

TEST(PiezoFields, StrainIn3DFollowsTheVoigtOrder) {
  auto mesh = std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {1, 2, 1}, 2, 2, 2));
  LinearFields f;
  f.G.resize(3, 3);
  f.G << 0.1, 0.2, 0.3, -0.4, 0.5, 0.6, 0.7, -0.8, 0.9;
  f.H = Eigen::MatrixXd::Zero(3, 3);
  const auto model = linear_model(mesh, 1, f, false);
  Eigen::VectorXd expected(6);  // xx, yy, zz, yz, xz, xy with engineering shear
  expected << 0.1, 0.5, 0.9, 0.6 - 0.8, 0.3 + 0.7, 0.2 - 0.4;
  expect_cells_equal(cell_strain(*model, "u"), expected, mesh->num_cells(), "strain");
}

TEST(PiezoFields, WrongFieldsAndMissingOrMisshapenConstantsAreNamed) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2));
  const auto model = linear_model(mesh, 1, fields_2d(), true);
  expect_error_containing([&] { cell_strain(*model, "phi"); }, {"'phi'", "1 components", "expected 2"});
  expect_error_containing([&] { cell_electric_field(*model, "u"); }, {"'u'", "2 components"});
  expect_error_containing([&] { cell_stress(*model); }, {"field 'u'", "constant 'B' (elasticity)"});
  model->set_constant("B", isotropic_stiffness(3, 1.0, 1.0));
  expect_error_containing([&] { cell_stress(*model); }, {"'B' (elasticity)", "6 x 6", "3 x 3"});
  model->set_constant("B", material_2d().B);
  expect_error_containing([&] { cell_stress(*model); }, {"field 'phi'", "constant 'E' (piezoelectric)"});
  model->set_constant("E", material_2d().E);
  expect_error_containing([&] { cell_electric_displacement(*model); }, {"constant 'beta' (permittivity)"});
}

TEST(VonMises, UniaxialStressIsItsMagnitudeAndShearScalesBySqrt3) {
  for (double s : {2.5, -4.0}) {
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> stress(6, 0.0);
      stress[axis] = s;
      EXPECT_DOUBLE_EQ(von_mises(stress, 3), std::abs(s));
    }
    EXPECT_DOUBLE_EQ(von_mises(std::vector<double>{s, 0, 0}, 2), std::abs(s));
    EXPECT_DOUBLE_EQ(von_mises(std::vector<double>{0, s, 0}, 2), std::abs(s));
    for (int shear = 3; shear < 6; ++shear) {
      std::vector<double> stress(6, 0.0);
      stress[shear] = s;
      EXPECT_DOUBLE_EQ(von_mises(stress, 3), std::sqrt(3.0) * std::abs(s));
    }
  }
  EXPECT_DOUBLE_EQ(von_mises(std::vector<double>{7, 7, 7, 0, 0, 0}, 3), 0.0);  // hydrostatic
}

TEST(VonMises, PlaneFormulaIsTheDocumentedInPlaneOne) {
  const std::vector<double> s = {1.5, -0.5, 0.25};
  EXPECT_DOUBLE_EQ(von_mises(s, 2), std::sqrt(1.5 * 1.5 + 1.5 * 0.5 + 0.25 + 3 * 0.0625));
  // Equal to the 3D formula with szz = 0.
  EXPECT_DOUBLE_EQ(von_mises(s, 2), von_mises(std::vector<double>{1.5, -0.5, 0, 0, 0, 0.25}, 3));
  expect_error_containing([&] { von_mises(s, 3); }, {"6 values", "got 3"});
}

TEST_F(OutputTest, AddPiezoOutputWritesThePresentFields) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2));
  const auto has_array = [](const std::string& text, const std::string& name) {
    return text.find("Name=\"" + name + "\"") != std::string::npos;
  };
  {
    const auto model = linear_model(mesh, 2, fields_2d(), true);
    set_constants(*model, material_2d());
    VtuWriter writer(*mesh);
    add_piezo_output(writer, *model);
    writer.write((directory_ / "piezo.vtu").string());
    const std::string text = read_text(directory_ / "piezo.vtu");
    for (const char* name :
         {"v", "u", "phi", "strain", "stress", "von_mises", "electric_field", "electric_displacement"})
      EXPECT_TRUE(has_array(text, name)) << name;
  }
  {
    const auto model = linear_model(mesh, 1, fields_2d(), false);
    model->set_constant("B", material_2d().B);
    VtuWriter writer(*mesh);
    add_piezo_output(writer, *model);
    writer.write((directory_ / "mechanical.vtu").string());
    const std::string text = read_text(directory_ / "mechanical.vtu");
    for (const char* name : {"v", "u", "strain", "stress", "von_mises"}) EXPECT_TRUE(has_array(text, name)) << name;
    for (const char* name : {"phi", "electric_field", "electric_displacement"})
      EXPECT_FALSE(has_array(text, name)) << name;
  }
}

TEST_F(OutputTest, AddPiezoOutputWritesOnlyTheWantedArrays) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2));
  const auto model = linear_model(mesh, 1, fields_2d(), true);
  set_constants(*model, material_2d());
  VtuWriter all(*mesh), some(*mesh);
  add_piezo_output(all, *model);
  add_piezo_output(some, *model, {}, [](const std::string& name) { return name == "phi" || name == "von_mises"; });
  all.write((directory_ / "all.vtu").string());
  some.write((directory_ / "some.vtu").string());
  const std::string text = read_text(directory_ / "some.vtu");
  EXPECT_EQ(testing::array_names(text, "PointData"), std::vector<std::string>{"phi"});
  EXPECT_EQ(testing::array_names(text, "CellData"), std::vector<std::string>{"von_mises"});
  // What is written is what a file of every array holds.
  const std::string every = read_text(directory_ / "all.vtu");
  EXPECT_EQ(testing::find_array(text, "PointData", "phi").bytes, testing::find_array(every, "PointData", "phi").bytes);
  EXPECT_EQ(testing::find_array(text, "CellData", "von_mises").bytes,
            testing::find_array(every, "CellData", "von_mises").bytes);
  // The arrays that share their strains and potential gradient equal the functions that compute them alone.
  EXPECT_EQ(testing::find_array(every, "CellData", "strain").doubles(), cell_strain(*model, "u"));
  EXPECT_EQ(testing::find_array(every, "CellData", "stress").doubles(), cell_stress(*model));
  EXPECT_EQ(testing::find_array(every, "CellData", "electric_field").doubles(), cell_electric_field(*model, "phi"));
  EXPECT_EQ(testing::find_array(every, "CellData", "electric_displacement").doubles(),
            cell_electric_displacement(*model));
}

// ---- boundary tables ----------------------------------------------------------------------------

TEST(BoundaryNodes, BottomNodesAreSortedByXAndCarryTheFieldValues) {
  const LinearFields f = fields_2d();
  const int nx = 4;
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({-1, 0}, {2, 1.5}, nx, 3));
  for (int order : {1, 2}) {
    SCOPED_TRACE(message("order ", order));
    const auto model = linear_model(mesh, order, f, true);
    const BoundaryNodes nodes = boundary_nodes(model->space("u"), "bottom", 0);
    ASSERT_EQ(nodes.points.size(), size_t(order * nx + 1));
    ASSERT_EQ(nodes.scalar_dofs.size(), nodes.points.size());
    for (size_t k = 0; k < nodes.points.size(); ++k) {
      EXPECT_DOUBLE_EQ(nodes.points[k][0], -1 + 3.0 * k / (order * nx));
      EXPECT_EQ(nodes.points[k][1], 0.0);
      EXPECT_EQ(nodes.points[k], model->space("u").scalar_dof_point(nodes.scalar_dofs[k]));
    }
    const auto ux = values_at_nodes(nodes, model->space("u"), model->values("u"), 0);
    const auto uy = values_at_nodes(nodes, model->space("u"), model->values("u"), 1);
    const auto phi = values_at_nodes(nodes, model->space("phi"), model->values("phi"), 0);
    for (size_t k = 0; k < nodes.points.size(); ++k) {
      const double x = nodes.points[k][0];
      EXPECT_NEAR(ux[k], f.G(0, 0) * x + 0.25, 1e-12);
      EXPECT_NEAR(uy[k], f.G(1, 0) * x + 0.25, 1e-12);
      EXPECT_NEAR(phi[k], f.p[0] * x + 1, 1e-12);
    }
  }
}

TEST(BoundaryNodes, TiesAreOrderedByTheOtherCoordinates) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2));
  const FESpace space(mesh, 1, 1);
  const BoundaryNodes nodes = boundary_nodes(space, "boundary", 0);
  ASSERT_EQ(nodes.points.size(), 8u);
  const std::vector<std::array<double, 2>> expected = {{0, 0},   {0, 0.5}, {0, 1},   {0.5, 0},
                                                       {0.5, 1}, {1, 0},   {1, 0.5}, {1, 1}};
  for (size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(nodes.points[k][0], expected[k][0]) << k;
    EXPECT_EQ(nodes.points[k][1], expected[k][1]) << k;
  }
  expect_error_containing([&] { boundary_nodes(space, "all", 0); }, {"'all'", "face region"});
  expect_error_containing([&] { boundary_nodes(space, "bottom", 2); }, {"axis 2", "2D"});
}

}  // namespace
}  // namespace pc
