// An OBJ text checked line after line, for the error a reader of the lines in order meets first: what
// parse_obj reports when one of its passes has found something wrong (model/obj_text.h). Every check and
// every message is the one rasterd's OBJ reader has had since it validated ahead of tinyobjloader.
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "model/obj_mtl.h"
#include "model/obj_text.h"

namespace raster::obj {
namespace {

// One index of a face/line/point reference, resolved like OBJ: 1-based, negative = relative to the end.
// Returns false (with `why`) when it is not an integer or does not name an element defined so far.
bool check_index(std::string_view text, std::int64_t defined, const char* what, std::string& why) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    why = std::string(what) + " index \"" + std::string(text) + "\" is not an integer";
    return false;
  }
  const std::int64_t resolved = value < 0 ? defined + value + 1 : value;
  if (value == 0 || resolved < 1 || resolved > defined) {
    why = std::string(what) + " index " + std::to_string(value) + " is out of range (" +
          std::to_string(defined) + " defined so far)";
    return false;
  }
  return true;
}

// Refuses a model once `count` passes `limit` (faces or points), naming the line that passed it.
void check_limit(std::int64_t count, std::int64_t limit, const char* what, std::size_t line_no) {
  if (count > limit)
    throw SceneError(ErrorKind::limit, "the model has more than " + std::to_string(limit) + " " + what,
                     ErrorLocation{"", 0, line_no});
}

// A face, line or point statement's references (the words after the keyword in `w`).
void check_references(Statement s, const std::vector<std::string_view>& w, const std::int64_t (&n)[3],
                      std::size_t line_no) {
  const std::size_t min_refs = s == Statement::f ? 3 : s == Statement::l ? 2 : 1;
  if (w.size() - 1 < min_refs)
    model_error(line_no, std::string(s == Statement::f   ? "a face"
                                     : s == Statement::l ? "a line"
                                                         : "a point") +
                             " needs at least " + std::to_string(min_refs) + " vertices");
  std::string why;
  for (std::size_t k = 1; k < w.size(); ++k) {  // v, v/vt, v//vn or v/vt/vn
    const Reference r = split_reference(w[k]);
    bool ok = check_index(r.vertex, n[0], "vertex", why);
    if (ok && !r.texture.empty()) ok = check_index(r.texture, n[1], "texture coordinate", why);
    if (ok && r.has_normal) ok = check_index(r.normal, n[2], "normal", why);
    if (!ok) model_error(line_no, why);
  }
}

}  // namespace

void check_obj_text(std::string_view text, const Limits& limits) {
  std::int64_t defined[3] = {};  // v, vt, vn lines so far
  std::int64_t faces = 0, point_refs = 0;
  detail::ReadMeter meter(limits);  // a line and each of its words a unit: one line may hold a huge face
  std::size_t line_no = 0;
  std::vector<std::string_view> w;
  for (std::size_t pos = 0; pos <= text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (inner_carriage_return(line))
      model_error(
          line_no,
          "a carriage return (CR) with more of the line after it: rasterd reads lines ended by LF or CR "
          "LF, not by CR alone (classic Mac OS); convert the line ends");
    split_words(line, w);
    meter.add(1 + w.size());
    LineWords words{line.data(), line.data() + line.size()};
    const Statement s = statement(words);  // the reader's statements: the others and comments draw nothing
    double d = 0;
    if (s == Statement::v) {
      if (w.size() < 4) model_error(line_no, "a vertex needs x y z");
      for (std::size_t k = 1; k < w.size() && k <= 6; ++k)
        if (!number(w[k], d) || std::fabs(d) > kMaxCoordinate)
          model_error(line_no, "vertex component \"" + std::string(w[k]) +
                                   "\" is not a finite number within +-3.4e38");
      ++defined[0];
    } else if (s == Statement::vt) {
      if (w.size() < 2) model_error(line_no, "a texture coordinate needs u (and v)");
      for (std::size_t k = 1; k < w.size() && k <= 3; ++k)
        // The bound a scene's "uvs" have: beyond it a coordinate would not survive its float conversion.
        if (!number(w[k], d) || std::fabs(d) > 1e30)
          model_error(line_no,
                      "texture coordinate \"" + std::string(w[k]) + "\" is not a number within +-1e30");
      ++defined[1];
    } else if (s == Statement::vn) {
      if (w.size() < 4) model_error(line_no, "a normal needs x y z");
      ++defined[2];
    } else if (s == Statement::f || s == Statement::l || s == Statement::p) {
      check_references(s, w, defined, line_no);
      if (s == Statement::f) check_limit(++faces, limits.max_model_faces, "faces", line_no);
      if (s == Statement::p) {
        point_refs += static_cast<std::int64_t>(w.size()) - 1;
        check_limit(point_refs, limits.max_model_points, "points", line_no);
      }
    }
  }
}

}  // namespace raster::obj
