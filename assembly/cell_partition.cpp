#include "assembly/cell_partition.hpp"

#include <metis.h>

#include "assembly/error.hpp"

namespace pc {

std::vector<int> partition_cells(const Mesh& mesh, int parts) {
  const int cells = mesh.num_cells();
  require(parts >= 1, "partition_cells: the number of parts must be >= 1, got ", parts);
  require(parts <= cells, "partition_cells: ", parts, " parts of a mesh of ", cells,
          " cells (each process must own a cell): run on fewer processes or refine the mesh");
  if (parts == 1) return std::vector<int>(static_cast<size_t>(cells), 0);
  idx_t ne = cells, nn = mesh.num_nodes();
  // Neighbours share a face: as many nodes as a face has (2 in 2D, 3 for tetrahedra, 4 for hexahedra).
  idx_t ncommon = idx_t(mesh.face_nodes(FaceRef{0, 0}).size());
  idx_t nparts = parts;
  std::vector<idx_t> eptr(static_cast<size_t>(cells) + 1), eind(mesh.connectivity().begin(), mesh.connectivity().end());
  for (int c = 0; c <= cells; ++c) eptr[size_t(c)] = idx_t(c) * mesh.vertices_per_cell();
  idx_t cut = 0;
  std::vector<idx_t> cell_part(static_cast<size_t>(cells)), node_part(static_cast<size_t>(nn));
  // Parts that hang together (fewer interface dofs, and a process's cells in one piece), unless the mesh
  // itself is in pieces, which METIS then refuses: its default partition is taken then.
  int status = METIS_ERROR;
  for (const bool contiguous : {true, false}) {
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_CONTIG] = contiguous ? 1 : 0;
    status = METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &nparts, nullptr,
                                options, &cut, cell_part.data(), node_part.data());
    if (status == METIS_OK) break;
  }
  require(status == METIS_OK, "partition_cells: METIS failed with status ", status, " on ", cells, " cells, ", parts,
          " parts");
  std::vector<int> owner(cell_part.begin(), cell_part.end());
  std::vector<int> sizes(size_t(parts), 0);
  for (int p : owner) ++sizes[size_t(p)];
  for (int p = 0; p < parts; ++p)
    require(sizes[size_t(p)] > 0, "partition_cells: METIS left part ", p, " of ", parts, " empty (", cells,
            " cells): run on fewer processes");
  return owner;
}

std::vector<char> cells_of_part(const std::vector<int>& owner, int part) {
  std::vector<char> owned(owner.size());
  for (size_t c = 0; c < owner.size(); ++c) owned[c] = owner[c] == part;
  return owned;
}

}  // namespace pc
