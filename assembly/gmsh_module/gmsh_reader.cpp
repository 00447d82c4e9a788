// The part of the gmsh import that links gmsh: built as a module of its own (libpiezocontact_gmsh.so),
// which assembly/gmsh_import.cpp opens on the first import. Linking gmsh into the engine cost every run
// 47 MiB of resident libraries and 0.1-0.15 s of relocations, read a gmsh mesh or not.
#include "assembly/gmsh_import.hpp"

#include <gmsh.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <thread>
#include <unordered_map>

#include "assembly/error.hpp"

namespace pc {
namespace {

// gmsh keeps its state in process-wide globals, and gmsh 4.8 cannot tell whether it is initialized.
// Each import therefore runs alone in a session of its own, opened and closed around it; a caller must
// not hold a gmsh session of its own open while importing.
std::mutex gmsh_mutex;

class GmshSession {
 public:
  GmshSession() { gmsh::initialize(0, nullptr, /*readConfigFiles=*/false); }
  ~GmshSession() {
    try {
      gmsh::finalize();
    } catch (...) {  // nothing useful can be done about a failure to clean up
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

struct Elements {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags;
  std::vector<std::vector<std::size_t>> nodes;
};

Elements get_elements(int dim, int entity = -1) {
  Elements e;
  gmsh::model::mesh::getElements(e.types, e.tags, e.nodes, dim, entity);
  return e;
}

struct ElementType {
  std::string name;
  int order = 0;
  int num_nodes = 0;
  int num_primary_nodes = 0;
};

// gmsh's element types up to order 2 (gmsh's MSH format documentation), by number. Known here rather than
// asked of gmsh: gmsh::model::mesh::getElementProperties builds each type's nodal basis with gmsh's own
// Eigen, which AddressSanitizer reports as a bad free when the caller was built with another one, so
// that the import could not be fuzzed under the sanitizers.
std::optional<ElementType> known_element_type(int type) {
  switch (type) {
    case 1: return ElementType{"Line 2", 1, 2, 2};
    case 2: return ElementType{"Triangle 3", 1, 3, 3};
    case 3: return ElementType{"Quadrilateral 4", 1, 4, 4};
    case 4: return ElementType{"Tetrahedron 4", 1, 4, 4};
    case 5: return ElementType{"Hexahedron 8", 1, 8, 8};
    case 6: return ElementType{"Prism 6", 1, 6, 6};
    case 7: return ElementType{"Pyramid 5", 1, 5, 5};
    case 8: return ElementType{"Line 3", 2, 3, 2};
    case 9: return ElementType{"Triangle 6", 2, 6, 3};
    case 10: return ElementType{"Quadrilateral 9", 2, 9, 4};
    case 11: return ElementType{"Tetrahedron 10", 2, 10, 4};
    case 12: return ElementType{"Hexahedron 27", 2, 27, 8};
    case 13: return ElementType{"Prism 18", 2, 18, 6};
    case 14: return ElementType{"Pyramid 14", 2, 14, 5};
    case 15: return ElementType{"Point", 0, 1, 1};
    case 16: return ElementType{"Quadrilateral 8", 2, 8, 4};
    case 17: return ElementType{"Hexahedron 20", 2, 20, 8};
    case 18: return ElementType{"Prism 15", 2, 15, 6};
    case 19: return ElementType{"Pyramid 13", 2, 13, 5};
    default: return std::nullopt;
  }
}

ElementType element_type(int type) {
  if (const auto known = known_element_type(type)) return *known;
  ElementType t;
  int dim = 0;
  std::vector<double> local_coordinates;
  gmsh::model::mesh::getElementProperties(type, t.name, dim, t.order, t.num_nodes, local_coordinates,
                                          t.num_primary_nodes);
  return t;
}

// The one cell shape of the elements of the mesh's top dimension.
Shape cell_shape(const Elements& cells) {
  std::string names;
  for (int type : cells.types) names += (names.empty() ? "" : ", ") + element_type(type).name;
  for (int type : cells.types)
    require(element_type(type).order == 1, "the mesh has second-order cells (", names,
            "); only first-order geometry is supported");
  require(cells.types.size() == 1, "the mesh mixes cell shapes (", names, "); a mesh must have one cell shape");
  switch (cells.types[0]) {
    case 2: return Shape::Triangle;
    case 3: return Shape::Quadrilateral;
    case 4: return Shape::Tetrahedron;
    case 5: return Shape::Hexahedron;
    default: break;
  }
  fail("the mesh has cells of type ", names,
       "; only triangles, quadrilaterals, tetrahedra and hexahedra are supported");
}

std::string physical_name(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  return name.empty() ? "physical_" + std::to_string(tag) : name;
}

// Signed area of a triangle or quadrilateral (shoelace formula) with 2D coordinates.
double signed_area(const std::vector<double>& coordinates, std::span<const int> polygon) {
  double twice_area = 0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const int a = polygon[k], b = polygon[(k + 1) % polygon.size()];
    twice_area += coordinates[2 * a] * coordinates[2 * b + 1] - coordinates[2 * b] * coordinates[2 * a + 1];
  }
  return twice_area / 2;
}

// Faces of the mesh by sorted node tuple, each named by the first cell that owns it.
class FaceFinder {
 public:
  explicit FaceFinder(const Mesh& mesh) {
    for (int c = 0; c < mesh.num_cells(); ++c)
      for (int f = 0; f < num_faces(mesh.cell_shape()); ++f) faces_.push_back({key(mesh.face_nodes({c, f})), {c, f}});
    std::stable_sort(faces_.begin(), faces_.end(), [](const Entry& a, const Entry& b) { return a.first < b.first; });
  }

  // The face with these nodes, or a FaceRef with cell -1.
  FaceRef find(std::vector<int> nodes) const {
    const auto wanted = key(std::move(nodes));
    const auto it = std::lower_bound(faces_.begin(), faces_.end(), wanted,
                                     [](const Entry& e, const std::vector<int>& k) { return e.first < k; });
    return it != faces_.end() && it->first == wanted ? it->second : FaceRef{};
  }

 private:
  using Entry = std::pair<std::vector<int>, FaceRef>;
  static std::vector<int> key(std::vector<int> nodes) {
    std::sort(nodes.begin(), nodes.end());
    return nodes;
  }
  std::vector<Entry> faces_;
};

void add_face_regions(Mesh& mesh, int face_dim, const std::unordered_map<std::size_t, int>& node_index) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, face_dim);
  if (groups.empty()) return;
  const FaceFinder finder(mesh);
  for (const auto& [dim, group] : groups) {
    const std::string name = physical_name(dim, group);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
    std::vector<FaceRef> faces;
    for (int entity : entities) {
      const Elements elements = get_elements(dim, entity);
      for (size_t t = 0; t < elements.types.size(); ++t) {
        const ElementType type = element_type(elements.types[t]);
        for (size_t e = 0; e < elements.tags[t].size(); ++e) {
          // Only the corner nodes identify a face (higher-order nodes follow them).
          const std::size_t* gmsh_nodes = elements.nodes[t].data() + e * type.num_nodes;
          std::vector<int> nodes;
          for (int k = 0; k < type.num_primary_nodes; ++k) {
            const auto it = node_index.find(gmsh_nodes[k]);
            nodes.push_back(it == node_index.end() ? -1 : it->second);
          }
          const FaceRef face = finder.find(nodes);
          if (face.cell < 0) {
            std::string tags;
            for (int k = 0; k < type.num_primary_nodes; ++k) tags += " " + std::to_string(gmsh_nodes[k]);
            fail("element ", elements.tags[t][e], " of physical group '", name, "' (gmsh nodes", tags,
                 ") is not a face of any cell");
          }
          faces.push_back(face);
        }
      }
    }
    mesh.add_face_region(name, std::move(faces));
  }
}

// Throws the error gmsh logged last, in the form of gmsh's own exceptions (a std::string).
void throw_logged_error() {
  std::string error;
  gmsh::logger::getLastError(error);
  if (!error.empty()) throw error;
}

void set_quiet_options(const GmshOptions& options) {
  gmsh::option::setNumber("General.Terminal", options.verbosity > 0 ? 1 : 0);
  gmsh::option::setNumber("General.Verbosity", options.verbosity);
  // gmsh logs errors instead of throwing them: an exception thrown from inside its .geo parser leaves
  // the parser's state corrupt, and every later parse in the process fails.
  gmsh::option::setNumber("General.AbortOnError", 0);
}

bool is_script(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return std::tolower(ch); });
  return extension == ".geo";
}

// In the child: reads the file (runs and meshes a script) and writes the mesh, exactly, to `msh`.
void read_in_child(const std::string& input, const std::string& msh, const GmshOptions& options) {
  set_quiet_options(options);
  gmsh::open(input);
  throw_logged_error();
  if (is_script(input)) {
    // Scale whatever factor the script sets for itself.
    double factor = 1;
    gmsh::option::getNumber("Mesh.MeshSizeFactor", factor);
    gmsh::option::setNumber("Mesh.MeshSizeFactor", factor * options.mesh_size_factor);
    gmsh::model::mesh::generate(gmsh::model::getDimension());
    throw_logged_error();
  }
  gmsh::option::setNumber("Mesh.Binary", 1);   // doubles bit for bit
  gmsh::option::setNumber("Mesh.SaveAll", 1);  // every element, as the script made them
  gmsh::write(msh);
  throw_logged_error();
}

// A statement missing its ';' is reported by gmsh at the next statement's line: name the line above too.
std::string with_line_hint(const std::string& geo, const std::string& error) {
  const auto at = error.find("', line ");
  if (at == std::string::npos || error.find("syntax error", at) == std::string::npos) return error;
  const int line = std::atoi(error.c_str() + at + 8);
  std::ifstream in(geo);
  std::string text, previous;
  int previous_line = 0;
  for (int n = 1; n < line && std::getline(in, text); ++n) {
    const auto end = text.find_last_not_of(" \t\r");
    if (end != std::string::npos && text.compare(0, 2, "//") != 0) {
      previous = text.substr(0, end + 1);
      previous_line = n;
    }
  }
  if (previous.empty() || std::string(";{(,").find(previous.back()) != std::string::npos) return error;
  // Statements end with ';'; block keywords (If, For, Macro, ...) do not.
  const size_t begin = previous.find_first_not_of(" \t");
  const std::string first_word = previous.substr(begin, previous.find_first_of(" \t(", begin) - begin);
  for (const char* block : {"If", "ElseIf", "Else", "EndIf", "For", "EndFor", "Macro", "Function", "Return"})
    if (first_word == block) return error;
  return message(error, " (line ", previous_line, " above it does not end with ';': '", previous, "')");
}

std::string describe_limit(double bytes) { return message(bytes / 1073741824.0, " GiB"); }

// Runs read_in_child in a child process within the budgets; returns the path of the .msh file it wrote,
// or throws saying how the child ended.
std::string read_in_child_process(const std::string& input, const GmshOptions& options) {
  const char* doing = is_script(input) ? "meshing" : "reading";
  const std::string msh = (std::filesystem::temp_directory_path() /
                           ("piezocontact_gmsh_" + std::to_string(::getpid()) + "_" +
                            std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()) + ".msh"))
                              .string();
  int channel[2];
  require(::pipe(channel) == 0, "gmsh: cannot create a pipe to read '", input, "': ", std::strerror(errno));
  std::fflush(nullptr);
  const pid_t child = ::fork();
  require(child >= 0, "gmsh: cannot start a process to read '", input, "': ", std::strerror(errno));
  if (child == 0) {
    ::close(channel[0]);
    // A crash inside gmsh ends the child by its signal, whatever handlers the parent installed (a
    // sanitizer's), so that the parent can say so.
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, SIG_DFL);
    if (options.verbosity <= 0) {  // what the script prints (Printf, warnings) is not the caller's output
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
    }
    if (options.max_memory_bytes > 0) {
      const rlimit limit{rlim_t(options.max_memory_bytes), rlim_t(options.max_memory_bytes)};
      ::setrlimit(RLIMIT_AS, &limit);
    }
    std::string error;
    int status = 0;
    try {
      const GmshSession session;
      read_in_child(input, msh, options);
    } catch (const std::string& e) {
      error = e;
      status = 2;
    } catch (const std::bad_alloc&) {
      error = "out of memory";
      status = 3;
    } catch (const std::exception& e) {
      error = e.what();
      status = 2;
    } catch (...) {
      error = "unknown error";
      status = 2;
    }
    // Within the pipe's buffer, so that the write never waits for a parent that waits for the exit.
    if (error.size() > 4000) error.resize(4000);
    for (size_t done = 0; done < error.size();) {
      const ssize_t n = ::write(channel[1], error.data() + done, error.size() - done);
      if (n <= 0) break;
      done += size_t(n);
    }
    ::_exit(status);  // no exit handlers of the parent's run in the child
  }
  ::close(channel[1]);
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  bool over_time = false;
  for (pid_t ended; (ended = ::waitpid(child, &status, WNOHANG)) == 0 || (ended < 0 && errno == EINTR);) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.max_seconds > 0 && elapsed > options.max_seconds) {
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
      over_time = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::string error;
  char buffer[4096];
  for (ssize_t n; (n = ::read(channel[0], buffer, sizeof buffer)) > 0;) error.append(buffer, size_t(n));
  ::close(channel[0]);
  auto remove_msh = [&] {
    std::error_code ignored;
    std::filesystem::remove(msh, ignored);
  };
  const std::string too_fine =
      is_script(input)
          ? message(": is the mesh size (mesh.size_factor = ", options.mesh_size_factor, ") far too small?")
          : std::string(": is the file a mesh too large for this machine?");
  if (over_time) {
    remove_msh();
    fail(doing, " took more than ", options.max_seconds, " s (mesh.max_seconds) and was stopped", too_fine);
  }
  const bool exited = WIFEXITED(status);
  const int code = exited ? WEXITSTATUS(status) : 0;
  if (exited && code == 0 && std::filesystem::exists(msh)) return msh;
  remove_msh();
  if (exited && code == 3 && !is_script(input))
    throw std::string(
        "reading it ran out of memory (a malformed count in the file, or a mesh too large for this "
        "machine)");
  if (exited && code == 3)
    fail(doing, " ran out of memory",
         options.max_memory_bytes > 0 ? " (the limit is " + describe_limit(options.max_memory_bytes) + ")" : "",
         too_fine);
  if (exited && code == 2) throw with_line_hint(input, error);
  if (exited && is_script(input))
    fail("the script ended gmsh (exit status ", code, ") before its mesh was written: does it call 'Exit'?");
  if (exited) fail("gmsh ended (exit status ", code, ") while reading the file (is it a malformed .msh?)");
  // A signal: libgmsh's own reader crashes on some malformed .msh files.
  fail("gmsh died of signal ", WTERMSIG(status), " (", strsignal(WTERMSIG(status)), ") while ", doing,
       is_script(input) ? "" : " the file (is it a malformed .msh?)",
       options.max_memory_bytes > 0 && (WTERMSIG(status) == SIGABRT || WTERMSIG(status) == SIGKILL)
           ? "; its memory was limited to " + describe_limit(options.max_memory_bytes) +
                 " (solver.max_memory_gib, or what the machine has available)"
           : "");
}

Mesh read_msh(const std::string& msh, const GmshOptions& options) {
  set_quiet_options(options);
  gmsh::open(msh);
  throw_logged_error();

  int top = 3;
  Elements cells = get_elements(top);
  if (cells.types.empty()) cells = get_elements(--top);
  require(!cells.types.empty(),
          "the mesh has no 2D or 3D cells (a .msh file written with physical groups keeps only the "
          "elements of those groups: give the domain a physical group, or set Mesh.SaveAll)");
  const Shape shape = cell_shape(cells);
  const std::vector<std::size_t>& cell_tags = cells.tags[0];
  const std::vector<std::size_t>& cell_nodes = cells.nodes[0];

  std::vector<std::size_t> node_tags;
  std::vector<double> node_xyz, parametric;
  gmsh::model::mesh::getNodes(node_tags, node_xyz, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> position;
  for (size_t n = 0; n < node_tags.size(); ++n) position.emplace(node_tags[n], n);

  // Keep the nodes of the cells only, numbered in increasing gmsh tag order.
  std::vector<std::size_t> used(cell_nodes.begin(), cell_nodes.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, int> node_index;
  std::vector<double> coordinates;
  coordinates.reserve(used.size() * top);
  double plane_z = 0;  // the z of every node of a 2D mesh, dropped from its coordinates
  for (size_t n = 0; n < used.size(); ++n) {
    const auto it = position.find(used[n]);
    require(it != position.end(), "cells refer to node ", used[n], ", which the file does not define");
    node_index.emplace(used[n], int(n));
    const double* xyz = node_xyz.data() + 3 * it->second;
    coordinates.insert(coordinates.end(), xyz, xyz + top);
    if (top == 2) {
      if (n == 0) plane_z = xyz[2];
      require(xyz[2] == plane_z, "the 2D cells do not lie in a plane z = ", plane_z, " (node ", used[n],
              " has z = ", xyz[2], "); surface meshes in 3D are not supported");
    }
  }

  const int per_cell = num_vertices(shape);
  std::vector<int> connectivity(cell_nodes.size());
  for (size_t k = 0; k < cell_nodes.size(); ++k) connectivity[k] = node_index.at(cell_nodes[k]);
  if (top == 2) {
    // gmsh orients a surface's elements along the surface's normal, which is -z when its boundary loop
    // runs clockwise. Such cells are correct, merely seen from the other side: reverse their vertex order
    // (keeping the first vertex) so that every cell is positively oriented in the xy plane.
    for (size_t c = 0; c < cell_tags.size(); ++c) {
      const std::span<int> polygon(connectivity.data() + c * per_cell, per_cell);
      if (signed_area(coordinates, polygon) < 0) std::reverse(polygon.begin() + 1, polygon.end());
    }
  }

  Mesh mesh(top, shape, std::move(coordinates), std::move(connectivity));

  std::unordered_map<std::size_t, int> cell_index;
  for (size_t c = 0; c < cell_tags.size(); ++c) cell_index.emplace(cell_tags[c], int(c));
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, top);
  for (const auto& [dim, group] : groups) {
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
    std::vector<int> region;
    for (int entity : entities)
      for (const auto& tags : get_elements(dim, entity).tags)
        for (std::size_t tag : tags) region.push_back(cell_index.at(tag));
    mesh.add_cell_region(physical_name(dim, group), std::move(region));
  }
  add_face_regions(mesh, top - 1, node_index);
  return mesh;
}

Mesh import_gmsh_in_module(const std::string& path, const GmshOptions& options) {
  require(std::filesystem::exists(path), "gmsh: cannot open '", path, "': no such file");
  require(std::filesystem::is_regular_file(path), "gmsh: cannot open '", path, "': not a regular file");
  require(options.mesh_size_factor > 0, "gmsh: mesh_size_factor must be positive, got ", options.mesh_size_factor);
  const std::lock_guard lock(gmsh_mutex);
  // gmsh 4.8 throws its error messages as std::string.
  try {
    // The child reads (or meshes) before this process opens a gmsh session of its own, and hands back a
    // binary .msh that gmsh itself wrote: this process never parses a file it was given.
    const std::string msh = read_in_child_process(path, options);
    struct RemoveTemporary {
      const std::string& path;
      ~RemoveTemporary() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
      }
    } temporary{msh};
    const GmshSession session;
    return read_msh(msh, options);
  } catch (const Error& e) {
    fail("gmsh: '", path, "': ", e.what());
  } catch (const std::string& e) {
    fail("gmsh: cannot read '", path, "': ", e);
  } catch (const std::exception& e) {
    fail("gmsh: cannot read '", path, "': ", e.what());
  } catch (...) {
    std::string last;
    try {
      gmsh::logger::getLastError(last);
    } catch (...) {  // the original failure is the one worth reporting
    }
    fail("gmsh: cannot read '", path, "': ", last.empty() ? "unknown error" : last);
  }
}

}  // namespace
}  // namespace pc

// The module's one entry point, looked up by name (unmangled) by the loader.
extern "C" __attribute__((visibility("default"))) void piezocontact_gmsh_import(const std::string& path,
                                                                                const pc::GmshOptions& options,
                                                                                std::optional<pc::Mesh>& mesh) {
  mesh.emplace(pc::import_gmsh_in_module(path, options));
}
