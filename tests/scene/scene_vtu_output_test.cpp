// The VTU keys of a scene: output.vtu_format chooses the files' format and output.vtu_fields their arrays;
// a bad value of either is refused naming the key and the value, and a run writes what they say.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "models/scene/scene.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/csv_table.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/test_helpers.hpp"
#include "support/vtu_reader.hpp"

namespace pc {
namespace {

namespace fs = std::filesystem;
using testing::expect_error_containing;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
const std::string kKnown =
    "known: v, u, phi, contact_pressure, contact_state, strain, stress, von_mises, electric_field, "
    "electric_displacement";

// The paper scene without its piezoelectric tensors: a purely mechanical body on an insulated foundation.
Scene mechanical_scene(const std::vector<std::string>& overrides) {
  Json json = read_json_file(kScene);
  Json material = Json::object();
  for (const auto& [key, value] : json.at("material").members())
    if (key != "piezo_E" && key != "permittivity_beta") material.set(key, value);
  json.set("material", material);
  Json foundation = Json::object();
  foundation.set("insulated", json.at("foundation").at("insulated"));
  json.set("foundation", foundation);
  apply_overrides(json, overrides);
  return load_scene(json, PIEZOCONTACT_SCENES);
}

TEST(SceneVtuKeys, DefaultsAreTheDefaultFormatAndEveryField) {
  const Scene scene = load_scene_file(kScene);
  EXPECT_EQ(scene.output.vtu_format, kDefaultVtuFormat);
  EXPECT_TRUE(scene.output.vtu_fields.empty());
  for (const SceneVtuField& f : scene_vtu_fields()) EXPECT_TRUE(scene.output.writes_vtu_field(f.name)) << f.name;
}

TEST(SceneVtuKeys, EveryFormatIsReadByName) {
  for (const std::string& name : vtu_format_names())
    EXPECT_EQ(to_string(load_scene_file(kScene, {"output.vtu_format=" + name}).output.vtu_format), name);
}

TEST(SceneVtuKeys, FieldsAreReadInTheirOrder) {
  const Scene scene = load_scene_file(kScene, {"output.vtu_fields=[\"von_mises\", \"u\", \"phi\"]"});
  EXPECT_EQ(scene.output.vtu_fields, (std::vector<std::string>{"von_mises", "u", "phi"}));
  EXPECT_TRUE(scene.output.writes_vtu_field("u"));
  EXPECT_FALSE(scene.output.writes_vtu_field("stress"));
  EXPECT_EQ(mechanical_scene({"output.vtu_fields=[\"u\", \"stress\"]"}).output.vtu_fields,
            (std::vector<std::string>{"u", "stress"}));
}

TEST(SceneVtuKeys, ABadFormatIsRefusedNamingTheKeyAndTheValue) {
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_format=xml"}); },
                          {"'output.vtu_format'", "unknown VTU format 'xml'", "known: ascii, base64, binary, zlib"});
  // Names are exact: no case folding.
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_format=ZLIB"}); },
                          {"'output.vtu_format'", "'ZLIB'"});
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_format=3"}); }, {"'output.vtu_format'", "string"});
}

TEST(SceneVtuKeys, BadFieldsAreRefusedNamingTheKeyAndTheValue) {
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_fields=[\"u\", \"stres\"]"}); },
                          {"'output.vtu_fields[1]' = 'stres' is not a field of the VTU files", kKnown});
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_fields=[\"u\", \"v\", \"u\"]"}); },
                          {"'output.vtu_fields[2]' = 'u' is listed twice"});
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_fields=[]"}); },
                          {"'output.vtu_fields' is empty", kKnown});
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_fields=u"}); }, {"'output.vtu_fields'", "array"});
  expect_error_containing([] { load_scene_file(kScene, {"output.vtu_fields=[1]"}); },
                          {"'output.vtu_fields[0]'", "string"});
  // A mechanical body has no potential to write.
  expect_error_containing([] { mechanical_scene({"output.vtu_fields=[\"u\", \"electric_field\"]"}); },
                          {"'output.vtu_fields[1]' = 'electric_field'", "not piezoelectric"});
}

class SceneVtuRun : public testing::TemporaryDirectoryTest {};

// The conductive foundation alone, no sweep, quiet, into out.
bool run_conductive(const Scene& scene, const fs::path& out) {
  SceneRunOptions options;
  options.output_directory = out.string();
  options.progress = false;
  options.only = {"conductive"};
  options.sweep = false;
  return run_scene(scene, options);
}

TEST_F(SceneVtuRun, ARunWritesItsSeriesInTheFormatAndWithTheFieldsTheSceneNames) {
  for (const std::string& format : vtu_format_names()) {
    SCOPED_TRACE(format);
    const fs::path out = directory_ / format;
    const Scene scene = load_scene_file(
        kScene, {"mesh.nx=6", "mesh.ny=2", "time.steps=4", "output.vtu_every=2", "output.vtu_format=" + format,
                 "output.vtu_fields=[\"contact_pressure\", \"phi\", \"von_mises\"]"});
    ASSERT_TRUE(run_conductive(scene, out));
    // The collection lists steps 0, 2 and 4, and each file holds just the named fields.
    const std::string pvd = testing::read_text(out / "conductive" / "paper2d.pvd");
    for (const char* step : {"paper2d_000000.vtu", "paper2d_000002.vtu", "paper2d_000004.vtu"}) {
      EXPECT_NE(pvd.find(std::string("file=\"") + step + "\""), std::string::npos) << step;
      const std::string vtu = testing::read_text(out / "conductive" / step);
      EXPECT_EQ(testing::array_names(vtu, "PointData"), (std::vector<std::string>{"phi", "contact_pressure"}));
      EXPECT_EQ(testing::array_names(vtu, "CellData"), (std::vector<std::string>{"von_mises"}));
      EXPECT_EQ(testing::find_array(vtu, "PointData", "phi").doubles().size(), size_t(7 * 3)) << step;
      EXPECT_EQ(testing::find_array(vtu, "CellData", "von_mises").doubles().size(), size_t(6 * 2 * 2)) << step;
      EXPECT_EQ(testing::element_attribute(vtu, "VTKFile", "compressor"),
                format == "zlib" ? "vtkZLibDataCompressor" : "");
    }
  }
}

TEST_F(SceneVtuRun, ByDefaultAFileHoldsEveryFieldInTheListedOrder) {
  const Scene scene = load_scene_file(kScene, {"mesh.nx=6", "mesh.ny=2", "time.steps=2", "output.vtu_every=2"});
  ASSERT_TRUE(run_conductive(scene, directory_));
  const std::string vtu = testing::read_text(directory_ / "conductive" / "paper2d_000002.vtu");
  std::vector<std::string> written = testing::array_names(vtu, "PointData");
  for (const std::string& name : testing::array_names(vtu, "CellData")) written.push_back(name);
  std::vector<std::string> all;
  for (const SceneVtuField& f : scene_vtu_fields()) {
    if (f.name != "space_error") {
      all.push_back(f.name);
      continue;
    }
    for (const char* field : {"u", "v", "phi"}) all.push_back(std::string("space_error_") + field);  // one per field
  }
  EXPECT_EQ(written, all);
}

// Three outputs read the contact law: the final table's pressure (gamma_c.csv), the contact history's last
// row (contact_state.csv) and the last VTU file's contact_pressure and contact_state. Node by node they must
// tell the same story: a node is separated exactly where its pressure is zero, and the VTU arrays carry the
// table's pressures and states on the same nodes.
TEST_F(SceneVtuRun, TheContactTableHistoryAndVtuAgreeNodeByNode) {
  const Scene scene = load_scene_file(
      kScene, {"mesh.nx=12", "mesh.ny=4", "time.steps=20", "output.vtu_every=20", "output.contact_history=true"});
  ASSERT_TRUE(run_conductive(scene, directory_));
  const fs::path dir = directory_ / "conductive";
  const testing::Table table = testing::read_csv(dir / "gamma_c.csv");
  const testing::Table history = testing::read_csv(dir / "contact_state.csv");
  ASSERT_EQ(table.rows.size(), size_t(13));
  ASSERT_FALSE(history.rows.empty());
  const std::vector<double>& states = history.rows.back();  // t, then one column per node in the table's order
  ASSERT_EQ(states.size(), table.rows.size() + 1);
  double table_pressure = 0;
  int table_pressed = 0;
  for (size_t i = 0; i < table.rows.size(); ++i) {
    const double pressure = table.rows[i][size_t(table.column("contact_pressure"))];
    EXPECT_GE(pressure, 0.0) << "node " << i;
    EXPECT_EQ(pressure > 0, states[i + 1] != 0)
        << "node " << i << ": pressure " << pressure << ", state " << states[i + 1];
    table_pressure += pressure;
    table_pressed += pressure > 0;
  }
  EXPECT_GT(table_pressed, 0);  // the body is pressed at the end of its loading
  const std::string vtu = testing::read_text(dir / "paper2d_000020.vtu");
  double vtu_pressure = 0;
  int vtu_pressed = 0;
  for (double p : testing::find_array(vtu, "PointData", "contact_pressure").doubles()) vtu_pressure += p;
  for (double s : testing::find_array(vtu, "PointData", "contact_state").doubles()) vtu_pressed += s != 0;
  EXPECT_NEAR(vtu_pressure, table_pressure, 1e-12 * table_pressure);
  EXPECT_EQ(vtu_pressed, table_pressed);
}

}  // namespace
}  // namespace pc
