#pragma once
/// \file msh_validation.hpp
/// A structural check of a Gmsh `.msh` file, run before Gmsh reads it (read_mesh_file() in
/// gmsh_io.hpp). Gmsh 4.8's parser trusts the file: a wrong count, a truncated section, an element
/// naming an undefined node or an entity bounded by an undeclared one can make it crash, loop,
/// allocate without bound or quietly read garbage. This check rejects such files with an InputError
/// whose key is "line L" (1-based line of the file) and whose message says what was expected there,
/// so Gmsh only ever sees well-formed structure. It checks the structure, not the geometry (inverted
/// or degenerate elements are found later, by Mesh::check()).
///
/// Accepted: ASCII MSH 2.x (2.0, 2.1, 2.2) and MSH 4.1, as written by Gmsh. Checked:
///  - $MeshFormat first, with a supported version, file type 0 (ASCII) and an integer data size;
///  - every section closed by its $End line, nothing but sections at the top level, each of
///    $MeshFormat, $PhysicalNames, $Entities, $Nodes and $Elements at most once, $Nodes before
///    $Elements, no other section (Gmsh matches section names by prefix and skips unknown ones in
///    ways that can swallow the next section, so none is let through);
///  - the lines Gmsh reads into 256-byte buffers (section lines, counts, physical names) fit in them;
///  - $PhysicalNames: the count, then `dim tag "name"` per line (dim 0..3, quoted name);
///  - $Entities (4.1): the four counts, the numbers of every point, curve, surface and volume
///    (finite bounding boxes, physical tags), and bounding entities that are declared;
///  - $Nodes: the counts (the blocks add up to the total, 4.1), node tags in [1, 2^31 − 1] and in
///    the header's [min, max] (4.1), no tag twice, entity blocks of a declared entity, finite
///    coordinates (TOML-like `nan`/`inf` are rejected here with the node's tag);
///  - $Elements: the counts, known element types with the right number of nodes and the dimension of
///    their entity block (4.1), MSH 2 tag lists (count ≥ 0, partition count within the list), and
///    every node an element names defined in $Nodes.
/// Rejected with a message saying why: binary files (save as ASCII), MSH 1, 3, 4.0 and later than 4.1,
/// and any other section, among them those Gmsh would interpret but symcontact does not use
/// ($NodeData, $ElementData, $ElementNodeData, $InterpolationScheme, $Periodic, $GhostElements,
/// $Parametrizations, $PartitionedEntities) and comments ($Comments).

#include <string>
#include <string_view>

namespace symcontact {

/// Checks the file at `path` as described above; throws InputError(file = path, key = "line L") on the
/// first fault, or InputError(path, "", ...) when it cannot be read.
void validate_msh_file(const std::string& path);

/// The same check on the text of a file; `file` is the name used in messages.
void validate_msh_text(std::string_view text, const std::string& file);

}  // namespace symcontact
