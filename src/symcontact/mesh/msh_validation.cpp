#include "symcontact/mesh/msh_validation.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {

/// Gmsh element types symcontact's reader may meet (gmsh.info, "MSH file format"): number of nodes and
/// dimension. Types outside this table are rejected here; types in it that symcontact cannot use
/// (order 3 and above) are rejected by read_mesh_file().
bool element_type_info(std::int64_t type, int& num_nodes, int& dim) {
  struct Info { int type, nodes, dim; };
  static const Info table[] = {
      {1, 2, 1},   {2, 3, 2},   {3, 4, 2},   {4, 4, 3},   {5, 8, 3},   {6, 6, 3},   {7, 5, 3},
      {8, 3, 1},   {9, 6, 2},   {10, 9, 2},  {11, 10, 3}, {12, 27, 3}, {13, 18, 3}, {14, 14, 3},
      {15, 1, 0},  {16, 8, 2},  {17, 20, 3}, {18, 15, 3}, {19, 13, 3}, {20, 9, 2},  {21, 10, 2},
      {26, 4, 1},  {29, 20, 3}};
  for (const Info& i : table) {
    if (i.type == type) {
      num_nodes = i.nodes;
      dim = i.dim;
      return true;
    }
  }
  return false;
}

constexpr std::int64_t kMaxTag = std::numeric_limits<std::int32_t>::max();
/// Gmsh reads some lines (section headers, physical names, MSH 2 counts) into 256-byte buffers.
constexpr std::size_t kMaxLineLength = 255;

/// The file as lines of whitespace-separated tokens, read one line at a time. Every failure is an
/// InputError(file, "line L", message).
class LineReader {
 public:
  LineReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  [[noreturn]] void fail(long line, const std::string& message) const {
    throw InputError(file_, "line " + std::to_string(line), message);
  }
  [[noreturn]] void fail(const std::string& message) const { fail(line_, message); }

  /// Reads the next line; false at the end of the text. Tokens are in tokens(), the line in raw().
  bool read() {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    raw_ = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    tokens_.clear();
    std::size_t i = 0;
    while (i < raw_.size()) {
      while (i < raw_.size() && is_space(raw_[i])) ++i;
      const std::size_t start = i;
      while (i < raw_.size() && !is_space(raw_[i])) {
        if (raw_[i] == '\0') fail("a NUL byte: this is not a text (ASCII) .msh file");
        ++i;
      }
      if (i > start) tokens_.push_back(raw_.substr(start, i - start));
    }
    return true;
  }

  /// The next line of section `section`, which must exist and not be empty (`what`: what it holds).
  void expect_line(const std::string& section, const std::string& what) {
    if (!read()) {
      fail("the file ends inside " + section + " (expected " + what + "): is it truncated?");
    }
    if (tokens_.empty()) fail("empty line inside " + section + " (expected " + what + ")");
  }

  /// The current line has exactly `n` tokens (or at least n when `at_least`).
  void expect_tokens(std::size_t n, const std::string& what, bool at_least = false) const {
    if (tokens_.size() == n || (at_least && tokens_.size() > n)) return;
    fail("expected " + what + " (" + (at_least ? "at least " : "") + std::to_string(n) + " value" +
         (n == 1 ? "" : "s") + "), got " + std::to_string(tokens_.size()));
  }

  std::int64_t integer(std::size_t k, const std::string& what, std::int64_t lo, std::int64_t hi) const {
    const std::string_view t = tokens_.at(k);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) {
      fail("expected " + what + " (an integer), got \"" + std::string(t) + "\"");
    }
    if (v < lo || v > hi) {
      fail("expected " + what + " in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
           std::to_string(v));
    }
    return v;
  }

  double real(std::size_t k, const std::string& what) const {
    const std::string t(tokens_.at(k));
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size()) fail("expected " + what + " (a number), got \"" + t + "\"");
    if (!std::isfinite(v)) fail("expected " + what + " to be a finite number, got \"" + t + "\"");
    return v;
  }

  const std::vector<std::string_view>& tokens() const { return tokens_; }
  std::string_view raw() const { return raw_; }
  long line() const { return line_; }
  /// The current line, stripped of surrounding white space.
  std::string_view trimmed() const {
    std::size_t a = 0, b = raw_.size();
    while (a < b && is_space(raw_[a])) ++a;
    while (b > a && is_space(raw_[b - 1])) --b;
    return raw_.substr(a, b - a);
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  long line_ = 0;
  std::string_view raw_;
  std::vector<std::string_view> tokens_;
};

/// The checks of one file: sections in turn, with what earlier sections declared.
class MshValidator {
 public:
  MshValidator(std::string_view text, const std::string& file) : in_(text, file) {}

  void run() {
    bool first = true;
    while (in_.read()) {
      if (in_.tokens().empty()) continue;
      short_line();
      const std::string_view header = in_.trimmed();
      if (header.size() < 2 || header[0] != '$' || in_.tokens().size() != 1) {
        in_.fail(first ? "expected $MeshFormat on the first line (a Gmsh .msh file), got \"" + excerpt() + "\""
                       : "expected a section header ($Name alone on its line), got \"" + excerpt() + "\"");
      }
      const std::string name(header.substr(1));
      if (first && name != "MeshFormat") in_.fail("expected $MeshFormat first, got $" + name);
      first = false;
      section(name);
    }
    if (first) in_.fail(1, "the file is empty (expected $MeshFormat)");
  }

 private:
  std::string excerpt() const {
    std::string s(in_.trimmed().substr(0, 40));
    for (char& c : s) {
      if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    }
    return s;
  }

  void once(const std::string& name) {
    auto [it, fresh] = seen_.emplace(name, in_.line());
    if (!fresh) in_.fail("a second $" + name + " section (the first is on line " + std::to_string(it->second) + ")");
  }

  void section(const std::string& name) {
    if (name.rfind("End", 0) == 0) in_.fail("$" + name + " without an opening $" + name.substr(3));
    if (name == "MeshFormat") {
      once(name);
      mesh_format();
    } else if (name == "PhysicalNames") {
      once(name);
      physical_names();
    } else if (name == "Entities") {
      once(name);
      if (version_ < 4) in_.fail("$Entities in an MSH " + version_text_ + " file (it belongs to MSH 4)");
      entities();
    } else if (name == "Nodes") {
      once(name);
      version_ < 4 ? nodes2() : nodes4();
    } else if (name == "Elements") {
      once(name);
      if (!seen_.count("Nodes")) in_.fail("$Elements before $Nodes (the nodes must come first)");
      version_ < 4 ? elements2() : elements4();
    } else {
      // Gmsh would interpret $NodeData, $Periodic, ... (and anything its prefix matching takes for a
      // section it knows), and skips the rest in ways that can swallow the next section: allow none.
      in_.fail("section $" + name + " is not supported by symcontact (a .msh file holds $MeshFormat, "
               "$PhysicalNames, $Entities, $Nodes and $Elements); save the mesh without it");
    }
    close(name);
  }

  /// The line after a section's content must be $End<name>.
  void close(const std::string& name) {
    const std::string end = "$End" + name;
    if (!in_.read()) in_.fail("the file ends inside $" + name + " (expected " + end + "): is it truncated?");
    short_line();
    if (in_.trimmed() != end) {
      in_.fail("expected " + end + " (the end of the section: is a count too small?), got \"" + excerpt() + "\"");
    }
  }

  /// Lines Gmsh reads into a 256-byte buffer (headers, counts, names) must fit in it.
  void short_line() const {
    if (in_.raw().size() > kMaxLineLength) {
      in_.fail("a line longer than " + std::to_string(kMaxLineLength) + " characters where Gmsh expects a short one");
    }
  }

  void mesh_format() {
    in_.expect_line("$MeshFormat", "version file-type data-size");
    short_line();
    in_.expect_tokens(3, "version file-type data-size");
    version_text_ = std::string(in_.tokens()[0]);
    const double v = in_.real(0, "the MSH version");
    if (v >= 2.0 && v < 3.0) {
      version_ = 2;
    } else if (v == 4.1) {
      version_ = 4;
    } else {
      in_.fail("MSH version " + version_text_ + " is not supported (expected 2.2 or 4.1, the ASCII formats Gmsh "
               "writes: Mesh.MshFileVersion)");
    }
    const std::int64_t type = in_.integer(1, "the file type", 0, 1);
    if (type != 0) {
      in_.fail("binary .msh files are not supported: save the mesh as ASCII (Gmsh: Mesh.Binary = 0)");
    }
    in_.integer(2, "the data size", 0, 64);
  }

  void physical_names() {
    const std::int64_t n = section_count("$PhysicalNames", "the number of physical names");
    for (std::int64_t k = 0; k < n; ++k) {
      in_.expect_line("$PhysicalNames", "dim tag \"name\" (" + std::to_string(n) + " names announced)");
      in_.expect_tokens(3, "dim tag \"name\"", true);
      in_.integer(0, "the dimension of a physical group", 0, 3);
      in_.integer(1, "a physical tag", -kMaxTag, kMaxTag);
      short_line();
      const std::string_view line = in_.trimmed();
      const std::size_t open = line.find('"');
      if (open == std::string_view::npos || line.size() < open + 2 || line.back() != '"' ||
          line.substr(open + 1, line.size() - open - 2).find('"') != std::string_view::npos) {
        in_.fail("expected the physical name in double quotes, got \"" + excerpt() + "\"");
      }
    }
  }

  /// $Entities (4.1): points "tag x y z nphys phys...", curves/surfaces/volumes "tag 6 numbers nphys
  /// phys... nbound bound...", bounding tags (signed) of declared entities one dimension lower.
  void entities() {
    in_.expect_line("$Entities", "numPoints numCurves numSurfaces numVolumes");
    short_line();
    in_.expect_tokens(4, "numPoints numCurves numSurfaces numVolumes");
    std::int64_t count[4];
    for (int d = 0; d < 4; ++d) count[d] = in_.integer(d, "an entity count", 0, kMaxTag);
    static const char* kind[] = {"point", "curve", "surface", "volume"};
    for (int d = 0; d < 4; ++d) {
      for (std::int64_t k = 0; k < count[d]; ++k) {
        const std::string what = std::string(kind[d]) + " entity (" + std::to_string(count[d]) + " announced)";
        in_.expect_line("$Entities", "a " + what);
        const std::size_t nx = d == 0 ? 3 : 6;
        in_.expect_tokens(2 + nx, "a " + what, true);
        const std::int64_t tag = in_.integer(0, std::string("a ") + kind[d] + " tag", 1, kMaxTag);
        for (std::size_t i = 1; i <= nx; ++i) in_.real(i, "a coordinate");
        std::size_t at = 1 + nx;
        const std::int64_t nphys = in_.integer(at, "the number of physical tags", 0, kMaxTag);
        if (static_cast<std::int64_t>(in_.tokens().size()) < static_cast<std::int64_t>(at) + 1 + nphys + (d > 0)) {
          in_.fail("expected " + std::to_string(nphys) + " physical tags" + (d > 0 ? " and the bounding entities" : "") +
                   ", the line is too short");
        }
        for (std::int64_t p = 0; p < nphys; ++p) in_.integer(at + 1 + p, "a physical tag", -kMaxTag, kMaxTag);
        at += 1 + nphys;
        if (d > 0) {
          const std::int64_t nb = in_.integer(at, "the number of bounding entities", 0, kMaxTag);
          in_.expect_tokens(at + 1 + nb, "the bounding " + std::string(kind[d - 1]) + "s");
          for (std::int64_t b = 0; b < nb; ++b) {
            const std::int64_t t = in_.integer(at + 1 + b, std::string("a bounding ") + kind[d - 1] + " tag", -kMaxTag, kMaxTag);
            if (!entities_[d - 1].count(std::llabs(t))) {
              in_.fail(std::string("bounding ") + kind[d - 1] + " " + std::to_string(t) + " of " + kind[d] + " " +
                       std::to_string(tag) + " is not declared");
            }
          }
        } else {
          in_.expect_tokens(at, "a point entity");
        }
        if (!entities_[d].insert(tag).second) {
          in_.fail(std::string(kind[d]) + " entity " + std::to_string(tag) + " is declared twice");
        }
      }
    }
  }

  void add_node(std::int64_t tag) {
    if (!nodes_.insert(tag).second) in_.fail("node " + std::to_string(tag) + " is defined twice");
  }

  void coordinates(std::size_t first, std::int64_t tag) {
    static const char* axis[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      const std::string t(in_.tokens()[first + i]);
      char* end = nullptr;
      const double v = std::strtod(t.c_str(), &end);
      if (t.empty() || end != t.c_str() + t.size()) {
        in_.fail("node " + std::to_string(tag) + ": expected the " + axis[i] + " coordinate (a number), got \"" + t + "\"");
      }
      if (!std::isfinite(v)) {
        in_.fail("node " + std::to_string(tag) + ": the " + axis[i] + " coordinate is not a finite number (got \"" + t + "\")");
      }
    }
  }

  void nodes2() {
    const std::int64_t n = section_count("$Nodes", "the number of nodes");
    for (std::int64_t k = 0; k < n; ++k) {
      in_.expect_line("$Nodes", "node tag x y z (" + std::to_string(n) + " nodes announced)");
      in_.expect_tokens(4, "node tag x y z");
      const std::int64_t tag = in_.integer(0, "a node tag", 1, kMaxTag);
      coordinates(1, tag);
      add_node(tag);
    }
  }

  /// The first line of a section that holds one count (`what`: its name in messages), in [0, kMaxTag].
  std::int64_t section_count(const std::string& section, const std::string& what) {
    in_.expect_line(section, what);
    short_line();
    in_.expect_tokens(1, what);
    return in_.integer(0, what, 0, kMaxTag);
  }

  /// The header of a MSH 4 $Nodes or $Elements section (`section` "Nodes" or "Elements", `item` "node" or
  /// "element"): numEntityBlocks numItems minItemTag maxItemTag, each in range.
  struct SectionCounts {
    long line = 0;
    std::int64_t blocks = 0, n = 0, lo = 0, hi = 0;
  };
  SectionCounts section_counts(const std::string& section, const std::string& item) {
    std::string Item = item;
    Item[0] = static_cast<char>(Item[0] - 'a' + 'A');
    const std::string names = "numEntityBlocks num" + Item + "s min" + Item + "Tag max" + Item + "Tag";
    in_.expect_line("$" + section, names);
    short_line();
    in_.expect_tokens(4, names);
    SectionCounts c;
    c.line = in_.line();
    c.blocks = in_.integer(0, "the number of entity blocks", 0, kMaxTag);
    c.n = in_.integer(1, "the number of " + item + "s", 0, kMaxTag);
    c.lo = in_.integer(2, "the smallest " + item + " tag", c.n == 0 ? 0 : 1, kMaxTag);
    c.hi = in_.integer(3, "the largest " + item + " tag", c.n == 0 ? 0 : c.lo, kMaxTag);
    return c;
  }

  /// The next block header line of `section` (`names`: its four fields): its entity dimension and tag.
  std::pair<int, std::int64_t> block_entity(const std::string& section, const std::string& names) {
    in_.expect_line(section, names);
    in_.expect_tokens(4, names);
    const int dim = static_cast<int>(in_.integer(0, "the entity dimension", 0, 3));
    return {dim, in_.integer(1, "the entity tag", 1, kMaxTag)};
  }

  /// The entity blocks of a MSH 4 section after its header (section_counts()): for each, its header line
  /// (`block_names`: entityDim entityTag, a third field, the number of items), `third(dim)` reading and
  /// checking the third field, then `items(c, dim, third, m)` reading the block's m items. The blocks' item
  /// counts must add up to the header's.
  void entity_blocks(const std::string& section, const std::string& item, const std::string& block_names,
                     const std::function<std::int64_t(int dim)>& third,
                     const std::function<void(const SectionCounts& c, int dim, std::int64_t third, std::int64_t m)>&
                         items) {
    const SectionCounts c = section_counts(section, item);
    std::int64_t total = 0;
    for (std::int64_t b = 0; b < c.blocks; ++b) {
      const auto [dim, entity] = block_entity("$" + section, block_names);
      const std::int64_t t = third(dim);
      const std::int64_t m = in_.integer(3, "the number of " + item + "s in the block", 0, c.n - total);
      known_entity(dim, entity);
      total += m;
      items(c, dim, t, m);
    }
    if (total != c.n) {
      in_.fail(c.line, "the " + item + " blocks hold " + std::to_string(total) + " " + item + "s, the $" + section +
                           " header announced " + std::to_string(c.n));
    }
  }

  void nodes4() {
    const auto parametric_flag = [this](int dim) {
      return in_.integer(2, "the parametric flag", 0, dim == 3 ? 0 : 1);
    };
    entity_blocks("Nodes", "node", "entityDim entityTag parametric numNodesInBlock", parametric_flag,
                  [this](const SectionCounts& c, int dim, std::int64_t parametric, std::int64_t m) {
                    std::vector<std::int64_t> tags;
                    tags.reserve(static_cast<std::size_t>(std::min<std::int64_t>(m, 1 << 20)));
                    for (std::int64_t k = 0; k < m; ++k) {
                      in_.expect_line("$Nodes", "a node tag (" + std::to_string(m) + " in this block)");
                      in_.expect_tokens(1, "a node tag");
                      tags.push_back(in_.integer(0, "a node tag", c.lo, c.hi));
                      add_node(tags.back());
                    }
                    const std::size_t nc = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
                    for (std::int64_t k = 0; k < m; ++k) {
                      in_.expect_line("$Nodes", "the coordinates of node " + std::to_string(tags[k]));
                      in_.expect_tokens(nc, "the coordinates of node " + std::to_string(tags[k]) +
                                                (parametric ? " and its parametric coordinates" : ""));
                      coordinates(0, tags[k]);
                      for (std::size_t i = 3; i < nc; ++i) in_.real(i, "a parametric coordinate");
                    }
                  });
  }

  /// An entity named by a node or element block must be declared when the file has $Entities.
  void known_entity(int dim, std::int64_t tag) {
    if (!seen_.count("Entities")) return;
    if (!entities_[dim].count(tag)) {
      in_.fail("entity (dimension " + std::to_string(dim) + ", tag " + std::to_string(tag) +
               ") is not declared in $Entities");
    }
  }

  void element_nodes(std::size_t first, std::size_t count, std::int64_t tag) {
    for (std::size_t i = first; i < first + count; ++i) {
      const std::int64_t v = in_.integer(i, "a node tag", 1, kMaxTag);
      if (!nodes_.count(v)) {
        in_.fail("element " + std::to_string(tag) + " refers to node " + std::to_string(v) +
                 ", which $Nodes does not define");
      }
    }
  }

  void elements2() {
    const std::int64_t n = section_count("$Elements", "the number of elements");
    for (std::int64_t k = 0; k < n; ++k) {
      in_.expect_line("$Elements", "tag type numTags tags... nodes... (" + std::to_string(n) + " elements announced)");
      in_.expect_tokens(3, "element tag, type, number of tags", true);
      const std::int64_t tag = in_.integer(0, "an element tag", 1, kMaxTag);
      const std::int64_t type = in_.integer(1, "an element type", 1, kMaxTag);
      int nn = 0, dim = 0;
      if (!element_type_info(type, nn, dim)) in_.fail("element " + std::to_string(tag) + ": unknown element type " + std::to_string(type));
      const std::int64_t ntags = in_.integer(2, "the number of tags", 0, 64);
      in_.expect_tokens(3 + static_cast<std::size_t>(ntags + nn),
                        "element " + std::to_string(tag) + ": " + std::to_string(ntags) + " tags and " +
                            std::to_string(nn) + " nodes");
      for (std::int64_t t = 0; t < ntags; ++t) in_.integer(3 + t, "an element tag list entry", -kMaxTag, kMaxTag);
      if (ntags >= 1) in_.integer(3, "the physical tag", 0, kMaxTag);
      if (ntags >= 2) in_.integer(4, "the elementary (entity) tag", 0, kMaxTag);
      if (ntags >= 3) in_.integer(5, "the number of partitions", 0, ntags - 3);
      element_nodes(3 + static_cast<std::size_t>(ntags), static_cast<std::size_t>(nn), tag);
    }
  }

  void elements4() {
    // The element type, of the block's dimension.
    const auto element_type = [this](int dim) {
      const std::int64_t type = in_.integer(2, "the element type", 1, kMaxTag);
      int nn = 0, type_dim = 0;
      if (!element_type_info(type, nn, type_dim)) in_.fail("unknown element type " + std::to_string(type));
      if (type_dim != dim) {
        in_.fail("element type " + std::to_string(type) + " has dimension " + std::to_string(type_dim) +
                 ", but the block's entity has dimension " + std::to_string(dim));
      }
      return type;
    };
    entity_blocks("Elements", "element", "entityDim entityTag elementType numElementsInBlock", element_type,
                  [this](const SectionCounts& c, int, std::int64_t type, std::int64_t m) {
                    int nn = 0, type_dim = 0;
                    element_type_info(type, nn, type_dim);
                    for (std::int64_t k = 0; k < m; ++k) {
                      in_.expect_line("$Elements",
                                      "elementTag nodeTags... (" + std::to_string(m) + " in this block)");
                      in_.expect_tokens(1 + static_cast<std::size_t>(nn),
                                        "an element tag and " + std::to_string(nn) + " node tags");
                      const std::int64_t tag = in_.integer(0, "an element tag", c.lo, c.hi);
                      element_nodes(1, static_cast<std::size_t>(nn), tag);
                    }
                  });
  }

  LineReader in_;
  int version_ = 0;
  std::string version_text_;
  std::map<std::string, long> seen_;  ///< section name -> line of its header
  std::unordered_set<std::int64_t> entities_[4];
  std::unordered_set<std::int64_t> nodes_;
};

}  // namespace

void validate_msh_text(std::string_view text, const std::string& file) { MshValidator(text, file).run(); }

void validate_msh_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the mesh file for reading");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path, "", "error while reading the mesh file");
  validate_msh_text(text, path);
}

}  // namespace symcontact
