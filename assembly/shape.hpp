#pragma once
// Reference shapes: the cells of a mesh and their faces. Reference cells are the unit simplex
// (vertices 0, e1, e2, e3) and the unit cube [0,1]^d; vertex and face numbering follow VTK/gmsh.
#include <array>
#include <span>
#include <string>

namespace pc {

enum class Shape { Point, Segment, Triangle, Quadrilateral, Tetrahedron, Hexahedron };

std::string to_string(Shape shape);
int dimension(Shape shape);
int num_vertices(Shape shape);
int num_faces(Shape shape);
int num_edges(Shape shape);
bool is_simplex(Shape shape);

// Reference coordinates of a vertex (unused trailing coordinates are zero).
std::array<double, 3> reference_vertex(Shape shape, int vertex);
// Local vertices of a face (codimension-one entity) and of an edge.
std::span<const int> face_vertices(Shape cell, int face);
std::span<const int> edge_vertices(Shape cell, int edge);
Shape face_shape(Shape cell, int face);

// Maps a point s of the face's reference shape to the cell's reference coordinates.
std::array<double, 3> face_to_cell(Shape cell, int face, const double* s);

}  // namespace pc
