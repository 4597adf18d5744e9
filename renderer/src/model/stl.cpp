// STL models: binary (an 80-byte header, a triangle count, 50 bytes per triangle) and ASCII ("solid ...
// facet normal ... outer loop vertex x y z ... endloop endfacet ... endsolid"). STL writes every corner of
// every facet in full; the corners are welded into shared vertices as they are read (model/weld.h: equal
// positions are one vertex), so a mesh of a million vertices costs the renderer a million, not the six
// million corners of its two million facets.
#include <algorithm>
#include <atomic>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <thread>

#include "base/budget_ask.h"
#include "base/parallel.h"
#include "base/text.h"
#include "model/reading.h"
#include "model/weld.h"
#include "raster/model.h"

namespace raster {
namespace {

using detail::iequals;  // STL's keywords are read in any ASCII case

[[noreturn]] void stl_error(const std::string& message, std::size_t line = 0, std::size_t byte = 0) {
  throw SceneError(ErrorKind::model, "STL: " + message, ErrorLocation{"", byte, line});
}

void check_facets(std::uint64_t facets, const Limits& limits) {
  if (facets > static_cast<std::uint64_t>(limits.max_model_faces))
    detail::too_many_faces(limits.max_model_faces);
}

std::uint32_t le_u32(const char* p) {
  std::uint32_t u = 0;
  for (int k = 3; k >= 0; --k) u = u << 8 | static_cast<unsigned char>(p[k]);
  return u;
}

// A little-endian IEEE float at p, as every STL writer stores it.
float le_float(const char* p) {
  std::uint32_t u;
  std::memcpy(&u, p, 4);
  if constexpr (std::endian::native == std::endian::big) u = __builtin_bswap32(u);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

// The welded positions: room for every corner of `facets` facets (the most there can be), whose pages are
// taken only as vertices are written; what is written is asked of the budget as it grows (ask()), so a
// closed mesh (about half as many vertices as facets) is charged for what it holds, not for a soup's three a
// facet.
class Positions {
 public:
  Positions(std::vector<Vec3f>& positions, std::uint64_t facets, const Limits& limits)
      : positions_(positions), limits_(limits) {
    detail::reserve_huge(positions_, static_cast<std::size_t>(3 * facets));
  }
  /// Room for three more (a facet's corners), asked of the budget in steps of 1 MiB.
  void ask() {
    const auto held = static_cast<std::int64_t>((positions_.size() + 3) * sizeof(Vec3f));
    if (held <= asked_) return;
    detail::reserve(limits_, kStep, [] { return std::string("the model's vertices"); });
    asked_ += kStep;
  }
  /// Room for the corners of `facets` more facets, when they outnumber what the text's size suggested
  /// (ASCII).
  void more(std::uint64_t facets) {
    if (positions_.size() + 3 * facets > positions_.capacity())
      detail::reserve_huge(positions_,
                           std::max<std::size_t>(positions_.size() + 3 * facets, 2 * positions_.capacity()));
  }

 private:
  static constexpr std::int64_t kStep = std::int64_t{1} << 20;
  std::vector<Vec3f>& positions_;
  const Limits& limits_;
  std::int64_t asked_ = 0;
};

// A closed mesh has about half as many vertices as triangles; a soup of separate facets three times as many
// (the welder grows to them).
std::size_t expected_vertices(std::uint64_t facets) {
  return static_cast<std::size_t>(facets / 2 + 3);
}

// Facet t's nine coordinates (12 bytes of facet normal, not read: see parse_stl; three corners of 12 bytes;
// 2 attribute bytes), and the first corner of it that is not a finite number (-1: none).
int load_facet(const char* facet, float (&v)[9]) {
  std::uint32_t exponents = 0;  // an exponent of all ones is an infinity or a NaN
  for (int k = 0; k < 9; ++k) {
    v[k] = le_float(facet + 12 + 4 * k);
    exponents |= (std::bit_cast<std::uint32_t>(v[k]) & 0x7f800000u) == 0x7f800000u;
  }
  if (exponents)
    for (int k = 0; k < 9; ++k)
      if (!std::isfinite(v[k])) return k / 3;
  return -1;
}

[[noreturn]] void not_finite(std::uint64_t facet, int corner) {
  stl_error("triangle " + std::to_string(facet + 1) + " has a corner that is not a finite number", 0,
            static_cast<std::size_t>(84 + 50 * facet + 12 + 12 * static_cast<std::uint64_t>(corner)) + 1);
}

// Binary facets of more than this many are welded on every thread the limits allow (weld_shared).
constexpr std::uint32_t kSharedFacets = 1u << 16;

// Welds facets [begin, end) into `positions` with `welder` (its vertices numbered from 0 in the order the
// range first names them), the corners' numbers into `corners`. The corner of the first facet that is not
// finite, when there is one, into `bad` (the range stops there).
void weld_range(std::string_view bytes, std::uint32_t begin, std::uint32_t end, detail::Welder& welder,
                Positions& room, std::uint32_t* corners, std::uint64_t& bad, const Limits& limits) {
  constexpr std::uint32_t kAhead = 32;  // facets: a table line fetched while 32 facets are read
  const bool prefetch = welder.table_bytes() > (std::size_t{1} << 20);
  detail::ReadMeter meter(limits);  // a corner or a triangle a unit, as for the other readers
  for (std::uint32_t t = begin; t < end; ++t) {
    meter.add(4);
    const char* p = bytes.data() + 84 + 50 * std::size_t{t};
    if (prefetch && t + kAhead < end)
      for (int k = 0; k < 3; ++k) {
        const char* c = p + 50 * kAhead + 12 + 12 * k;
        __builtin_prefetch(welder.slot_of(le_float(c), le_float(c + 4), le_float(c + 8)));
      }
    float v[9];
    if (const int wrong = load_facet(p, v); wrong >= 0) {
      bad = 3 * std::uint64_t{t} + static_cast<std::uint64_t>(wrong);
      return;
    }
    room.ask();
    for (int k = 0; k < 3; ++k)
      corners[3 * std::size_t{t} + k] = welder.vertex(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
  }
}

// The facets' corners welded on `threads` threads at once, into the same mesh one thread makes: the facets
// in ranges, one a thread, each welded into vertices of its own (the first straight into the mesh), then
// each later range's vertices, in the order it first named them, welded into the first's (a vertex the
// mesh has keeps its number, a new one is numbered next: the order the file first names them), and its
// corners renumbered.
void weld_shared(std::string_view bytes, std::uint32_t count, Mesh& mesh, const Limits& limits, int threads) {
  const auto n = static_cast<std::uint32_t>(threads);
  struct Range {
    std::vector<Vec3f> own;         ///< a later range's vertices (the first's are the mesh's)
    std::vector<Vec3f>* positions;  ///< where its vertices go
    std::optional<Positions> room;  ///< their pages, asked for as they are written
    std::optional<detail::Welder> welder;
    std::uint64_t bad = UINT64_MAX;  ///< the first corner that is not finite, if any
  };
  std::vector<Range> ranges(n);
  const std::size_t expected = expected_vertices(count) / n + 1024;
  auto* corners = reinterpret_cast<std::uint32_t*>(mesh.triangles.data());
  auto bounds = [&](std::uint32_t k) { return static_cast<std::uint32_t>(std::uint64_t{count} * k / n); };
  detail::run_pieces(threads, n, [&](std::size_t k) {
    Range& r = ranges[k];
    r.positions = k == 0 ? &mesh.positions : &r.own;
    const std::uint32_t begin = bounds(static_cast<std::uint32_t>(k)),
                        end = bounds(static_cast<std::uint32_t>(k) + 1);
    r.room.emplace(*r.positions, k == 0 ? count : end - begin, limits);  // the first takes the others' in too
    if (k > 0)  // the first range's table is the reader's first ask
      detail::reserve(limits, static_cast<std::int64_t>(detail::Welder::table_bytes(expected)),
                      [] { return std::string("the model's welding tables"); });
    // The first range's table takes every range's vertices in the end: made for all of them at once.
    r.welder.emplace(*r.positions, expected, limits);
    weld_range(bytes, begin, end, *r.welder, *r.room, corners, r.bad, limits);
    if (k > 0) r.welder->release();
  });
  for (const Range& r : ranges)
    if (r.bad != UINT64_MAX) not_finite(r.bad / 3, static_cast<int>(r.bad % 3));
  detail::Welder& mesh_welder = *ranges[0].welder;
  Positions& room = *ranges[0].room;
  for (std::uint32_t k = 1; k < n; ++k) {
    Range& r = ranges[k];
    detail::reserve(limits, static_cast<std::int64_t>(r.own.size() * sizeof(std::uint32_t)),
                    [] { return std::string("the model's vertices"); });
    std::vector<std::uint32_t> number(r.own.size());
    // The last range's new vertices need no table: no later range looks for them.
    const bool last = k + 1 == n;
    constexpr std::size_t kAhead = 16;  // vertices: their table lines fetched this far ahead
    for (std::size_t i = 0; i < r.own.size(); ++i) {
      if (i + kAhead < r.own.size()) {
        const Vec3f& q = r.own[i + kAhead];
        __builtin_prefetch(mesh_welder.slot_of(q.x, q.y, q.z));
      }
      room.ask();
      const Vec3f& p = r.own[i];
      if (!last) {
        number[i] = mesh_welder.vertex(p.x, p.y, p.z);
        continue;
      }
      const std::uint32_t found = mesh_welder.find(p.x, p.y, p.z);
      number[i] = found != UINT32_MAX ? found : static_cast<std::uint32_t>(mesh.positions.size());
      if (found == UINT32_MAX) mesh.positions.push_back(p);
    }
    // Freed, but their reservations kept to the end: an array below malloc's mmap threshold (the service's
    // is 16 MiB) is freed into the heap, where it stays resident until something reuses it, and the render's
    // large arrays are mapped apart (base/memory.h); given back, a 400k-facet STL's render peaked over what
    // it had reserved (tests/memory_estimate_test). A budget's error must be to the safe side.
    r.own = {};
    const std::size_t first = 3 * std::size_t{bounds(k)}, end = 3 * std::size_t{bounds(k + 1)};
    for (std::size_t c = first; c < end; ++c) corners[c] = number[corners[c]];
  }
  mesh_welder.release();
}

// The facets straight from the bytes: 50 each, every corner checked finite and welded as it is read. The
// welder's table is looked up a few facets ahead of time (a prefetch), since a large model's table is far
// larger than the cache. A large model is welded on every thread the limits allow (weld_shared).
Mesh read_binary(std::string_view bytes, const Limits& limits) {
  const std::uint32_t count = le_u32(bytes.data() + 80);
  // sniff_model matched the size to the count already; a caller naming the format did not. Bytes after the
  // triangles (some writers pad the file) are left unread; triangles the bytes do not hold are an error.
  if (bytes.size() < 84 + 50 * std::uint64_t{count})
    stl_error("a binary STL of " + std::to_string(count) + " triangles is " +
                  std::to_string(84 + 50 * std::uint64_t{count}) + " bytes; this one has only " +
                  std::to_string(bytes.size()),
              0, 81);
  if (count == 0) stl_error("the model has no triangles");
  check_facets(count, limits);
  Mesh mesh;
  mesh.shading = Shading::flat;
  mesh.crease_deg = kModelCreaseDeg;  // for a picture that asks for smooth shading
  const std::size_t expected = expected_vertices(count);
  detail::reserve(
      limits,
      static_cast<std::int64_t>(count * sizeof(mesh.triangles[0]) + detail::Welder::table_bytes(expected)),
      [&] { return "the model's " + std::to_string(count) + " facets"; });
  detail::reserve_huge(mesh.triangles, count);
  mesh.triangles.resize(count);
  const int threads =
      std::min(15, limits.threads > 0 ? limits.threads
                                      : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  if (threads > 1 && count > kSharedFacets) {
    weld_shared(bytes, count, mesh, limits, threads);
    return mesh;
  }
  Positions positions(mesh.positions, count, limits);
  detail::Welder welder(mesh.positions, expected, limits);
  constexpr std::uint32_t kAhead = 32;  // facets: a table line fetched while 32 facets are read
  const bool prefetch = welder.table_bytes() > (std::size_t{1} << 20);
  const char* p = bytes.data() + 84;
  detail::ReadMeter meter(limits);  // a corner or a triangle a unit, as for the other readers
  for (std::uint32_t t = 0; t < count; ++t, p += 50) {
    meter.add(4);
    if (prefetch && t + kAhead < count)
      for (int k = 0; k < 3; ++k) {
        const char* c = p + 50 * kAhead + 12 + 12 * k;
        __builtin_prefetch(welder.slot_of(le_float(c), le_float(c + 4), le_float(c + 8)));
      }
    float v[9];
    if (const int wrong = load_facet(p, v); wrong >= 0) not_finite(t, wrong);
    positions.ask();
    mesh.triangles[t] = {welder.vertex(v[0], v[1], v[2]), welder.vertex(v[3], v[4], v[5]),
                         welder.vertex(v[6], v[7], v[8])};
  }
  welder.release();
  return mesh;
}

// Words of an ASCII STL, with the line each is on.
class Words {
 public:
  explicit Words(std::string_view text) : text_(text) {}
  // The next word, or "" at the end.
  std::string_view next() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n')
        ++line_;
      else if (c != ' ' && c != '\t' && c != '\r' && c != '\f' && c != '\v')
        break;
      ++at_;
    }
    const std::size_t start = at_;
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') break;
      ++at_;
    }
    return text_.substr(start, at_ - start);
  }
  void skip_line() {
    const std::size_t eol = text_.find('\n', at_);
    at_ = eol == std::string_view::npos ? text_.size() : eol;
  }
  std::size_t line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t at_ = 0, line_ = 1;
};

std::string quoted(std::string_view word) {
  if (word.empty()) return "the end of the file";
  std::string out(1, '"');  // built by appending: g++ 12 warns falsely (-Wrestrict) on "\"" + string
  out.append(word.substr(0, 40)).push_back('"');
  return out;
}

double number(Words& in) {
  std::string_view w = in.next();
  if (w.size() > 1 && w[0] == '+') w.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
  if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v))
    stl_error("expected a number, got " + quoted(w), in.line());
  if (std::fabs(v) > kMaxCoordinate)
    stl_error("the coordinate " + quoted(w) + " is beyond +-2^128, the largest rasterd draws", in.line());
  return v;
}

void expect(Words& in, std::string_view keyword) {
  const std::string_view w = in.next();
  if (!iequals(w, keyword))
    stl_error("expected \"" + std::string(keyword) + "\", got " + quoted(w), in.line());
}

Mesh read_ascii(std::string_view text, const Limits& limits) {
  Words in(text);
  Mesh mesh;
  mesh.shading = Shading::flat;
  mesh.crease_deg = kModelCreaseDeg;  // for a picture that asks for smooth shading
  // A facet is at least ~60 bytes of text ("facet normal 0 0 0 outer loop vertex 0 0 0 ... endfacet"):
  // reserving from that bounds the guess by the text's size.
  std::size_t reserved = text.size() / 64;  // facets asked of the budget so far, grown in steps below
  const std::size_t expected = expected_vertices(reserved);
  detail::reserve(
      limits,
      static_cast<std::int64_t>(reserved * sizeof(mesh.triangles[0]) + detail::Welder::table_bytes(expected)),
      [] { return std::string("the model's facets"); });
  mesh.triangles.reserve(reserved);
  Positions positions(mesh.positions, reserved, limits);
  detail::Welder welder(mesh.positions, expected, limits);
  std::vector<std::uint32_t> corners;  // the facet's welded corners
  detail::ReadMeter meter(limits);     // a facet line or corner a unit: the deadline is asked as lines go by
  std::string_view w = in.next();
  if (!iequals(w, "solid")) stl_error("expected \"solid\", got " + quoted(w), in.line());
  in.skip_line();  // the solid's name
  while (true) {
    meter.add(1);  // the facet (or solid): with its corners below, 4 units a triangle as binary facets
    w = in.next();
    if (iequals(w, "endsolid")) {
      in.skip_line();
      w = in.next();
      if (w.empty()) break;
      if (!iequals(w, "solid"))
        stl_error("expected \"solid\" or the end of the file, got " + quoted(w), in.line());
      in.skip_line();
      continue;
    }
    if (!iequals(w, "facet")) stl_error("expected \"facet\" or \"endsolid\", got " + quoted(w), in.line());
    expect(in, "normal");
    for (int k = 0; k < 3; ++k) in.next();  // not read (see parse_stl): writers put "nan" here for slivers
    expect(in, "outer");
    expect(in, "loop");
    const std::size_t facet_line = in.line();
    corners.clear();
    while (true) {
      w = in.next();
      if (iequals(w, "endloop")) break;
      if (!iequals(w, "vertex")) stl_error("expected \"vertex\" or \"endloop\", got " + quoted(w), in.line());
      const double x = number(in), y = number(in), z = number(in);
      positions.more(1), positions.ask();
      const Vec3f p(Vec3{x, y, z});
      corners.push_back(welder.vertex(p.x, p.y, p.z));
      meter.add(1);
    }
    if (corners.size() < 3)
      stl_error("a facet has " + std::to_string(corners.size()) + " vertices; it needs 3", facet_line);
    // A loop of more than three corners (which some writers emit for planar polygons) as a fan.
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      check_facets(mesh.triangles.size() + 1, limits);
      if (mesh.triangles.size() == reserved) {  // fans of many corners: more triangles than the text's guess
        detail::stop_if_expired(limits);
        detail::reserve(limits, static_cast<std::int64_t>((reserved + 1) * sizeof(mesh.triangles[0])),
                        [] { return std::string("the model's facets"); });
        reserved = 2 * reserved + 1;
        mesh.triangles.reserve(reserved);
      }
      mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
    }
    expect(in, "endfacet");
  }
  if (mesh.triangles.empty()) stl_error("the model has no facets");
  welder.release();
  return mesh;
}

}  // namespace

Mesh parse_stl(std::string_view bytes, const Limits& limits) {
  // ASCII when it starts with "solid", unless its second line is not a facet and its size holds the
  // triangles its header counts: some binary writers start the header with "solid" too (and some pad the
  // file). Text's bytes 80..83 count at least 0x09090909 triangles, which no text is long enough to hold.
  Words words(bytes);
  const bool solid = iequals(words.next(), "solid");
  words.skip_line();
  const std::string_view second = words.next();
  const bool binary_size =
      bytes.size() >= 84 && bytes.size() >= 84 + 50 * std::uint64_t{le_u32(bytes.data() + 80)};
  if (solid && (!binary_size || iequals(second, "facet") || iequals(second, "endsolid")))
    return read_ascii(bytes, limits);
  if (bytes.size() < 84)
    stl_error("the file is " + std::to_string(bytes.size()) +
              " bytes: shorter than a binary STL's 84-byte header, and not ASCII STL (\"solid ...\")");
  return read_binary(bytes, limits);
}

}  // namespace raster
