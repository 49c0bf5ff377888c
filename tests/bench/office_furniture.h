// The pieces of the generated furnished office (furnished_office_scene.h): desks on thin metal
// legs with what lies on them, office and visitor chairs, bookshelves full of books, potted
// plants, bins, cardboard boxes and a filing cabinet. Each piece appends closed, outward-facing
// solids (solid_mesh.h) to the mesh of its material; plant leaves go to the two-sided "leaf"
// material. Metres, z up; a piece stands on the floor (z = 0) unless told otherwise.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "radiant/scene.h"
#include "seeded_random.h"

namespace radiant::bench {

/// Triangle meshes by surface name, in a fixed order: a material's name (furniture_materials()),
/// or "material/part" for a part kept in a surface of its own (each plant's leaves: one open
/// surface of thousands of triangles makes closed-surface checks slow).
using MaterialMeshes = std::map<std::string, MeshGeometry>;

/// The material of the surface `name` of a MaterialMeshes: its part before any '/'.
std::string material_of(const std::string& name);

/// Every material a piece may use: woods, metal, fabrics, plastics, paper, twelve book colours,
/// terracotta, cardboard and the two-sided leaf.
std::vector<Material> furniture_materials();

/// Where a piece stands: `origin` on its floor (or desk top), and the turn about the vertical
/// that takes the piece's own +x and +y to the room's.
struct Placement {
    Vec3 origin;
    double yaw_rad = 0;

    Vec3 direction(Vec3 local) const;  ///< a piece's vector in room coordinates
    Vec3 at(Vec3 local) const;         ///< a piece's point in room coordinates
};

/// Desk height (top of the board), metres.
inline constexpr double kDeskTopM = 0.745;

/// A 1.6 × 0.8 m desk centred on the placement, its length along +x and the user on −y: a 25 mm
/// board on four 40 mm round metal legs (octagonal prisms) and a metal modesty panel at +y.
void add_desk(MaterialMeshes& meshes, const Placement& at);

/// What is on a desk (the desk's placement): one or two monitors (or a laptop), keyboard, mouse,
/// and by chance a mug, papers and a stack of books.
void add_desk_clutter(MaterialMeshes& meshes, const Placement& desk, SeededRandom& random);

/// A swivel chair whose sitter faces +y: five-star base on casters, gas column, seat, reclined
/// backrest, by chance armrests.
void add_office_chair(MaterialMeshes& meshes, const Placement& at, SeededRandom& random);

/// A visitor chair on four thin legs, its sitter facing +y.
void add_visitor_chair(MaterialMeshes& meshes, const Placement& at);

/// A 0.9 m wide, 0.36 m deep, 2 m high bookshelf whose back stands on the placement's origin and
/// whose open front faces +y, its five compartments filled with books of random sizes and
/// colours (upright, some lying in stacks, some leaning). Returns the number of books.
int add_bookshelf(MaterialMeshes& meshes, const Placement& at, SeededRandom& random);

/// A plant in a terracotta pot on the floor: a few stems carrying leaves, `triangles` in all
/// (about; the leaves make up the difference).
void add_floor_plant(MaterialMeshes& meshes, Vec3 base, int triangles, SeededRandom& random);

/// A small plant (a rosette of long leaves) in a pot standing on a surface at base.z; no leaf
/// falls below that surface. About `triangles` triangles.
void add_small_plant(MaterialMeshes& meshes, Vec3 base, int triangles, SeededRandom& random);

/// A waste bin (a closed 12-sided frustum) standing at `base`.
void add_bin(MaterialMeshes& meshes, Vec3 base);

/// Two to four cardboard boxes stacked at the placement.
void add_cardboard_boxes(MaterialMeshes& meshes, const Placement& at, SeededRandom& random);

/// A 0.8 m wide, 0.45 m deep, 1.1 m high filing cabinet with three drawer handles at +y.
void add_filing_cabinet(MaterialMeshes& meshes, const Placement& at);

/// Triangles of all the meshes.
std::size_t triangle_count(const MaterialMeshes& meshes);

}  // namespace radiant::bench
