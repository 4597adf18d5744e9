// glTF's mesh building: the document, loaded by gltf.cpp, -> one Mesh. The default scene's node trees are
// walked without recursion; each node's mesh primitives add their positions (under the node's transform),
// normals (under its inverse transpose), colours (linear factors and COLOR_0 to sRGB bytes), materials and
// textures (decoded once per image and alpha mode), texture coordinates and faces (triangles, strips,
// fans, lines), each accessor read through AccessorView, which has checked its bytes.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "base/memory.h"
#include "model/gltf_document.h"
#include "model/reading.h"

namespace raster::gltf {
namespace {

// Mesh primitives drawn (a mesh's primitives once for each node that names it): each costs a few
// microseconds even when empty, so this bounds a model's reading to seconds, far above real scenes'
// thousands.
constexpr std::size_t kMaxDrawnPrimitives = 1 << 20;
// What reading one primitive costs beyond its elements, in units of the deadline meter (detail::ReadMeter):
// a few microseconds, as about a thousand vertices cost.
constexpr std::uint64_t kPrimitiveWork = 1024;

double srgb_of_linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

using Mat = std::array<double, 16>;  // column-major, as glTF stores it
constexpr Mat kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat multiply(const Mat& a, const Mat& b) {
  Mat r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
  return r;
}

Mat local_matrix(const tinygltf::Node& node) {
  Mat m = kIdentity;
  if (node.matrix.size() == 16) {
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  // T * R * S
  double s[3] = {1, 1, 1}, q[4] = {0, 0, 0, 1}, t[3] = {0, 0, 0};
  if (node.scale.size() == 3) std::copy(node.scale.begin(), node.scale.end(), s);
  if (node.rotation.size() == 4) std::copy(node.rotation.begin(), node.rotation.end(), q);
  if (node.translation.size() == 3) std::copy(node.translation.begin(), node.translation.end(), t);
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                       2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                       2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) m[c * 4 + row] = r[c * 3 + row] * s[c];
  m[12] = t[0], m[13] = t[1], m[14] = t[2];
  return m;
}

// One Mesh built from the primitives of every node drawn, in the order the nodes are visited.
class MeshBuilder {
 public:
  MeshBuilder(const tinygltf::Model& model, const Limits& limits, const Uploads& files, std::uint64_t sent)
      : model_(model), limits_(limits), files_(files), sent_(sent) {}

  Mesh read() {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (static_cast<std::size_t>(s) >= model_.scenes.size())
        gltf_error("the default scene " + std::to_string(s) + " does not exist");
      roots = model_.scenes[static_cast<std::size_t>(s)].nodes;
    } else if (model_.nodes.empty()) {  // no scenes and no nodes: every mesh as it is
      for (std::size_t i = 0; i < model_.meshes.size(); ++i) add_mesh(static_cast<int>(i), kIdentity);
    } else {  // no scenes: every node that is no other node's child
      std::vector<bool> child(model_.nodes.size());
      for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && static_cast<std::size_t>(c) < child.size()) child[static_cast<std::size_t>(c)] = true;
      for (std::size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(static_cast<int>(i));
    }
    counts_ = check_what_it_builds(model_, roots, model_.scenes.empty() && model_.nodes.empty(), sent_,
                                   kMaxDrawnPrimitives);
    visited_.assign(model_.nodes.size(), false);
    // Depth first without recursion: a document's nesting cannot exhaust the stack.
    std::vector<std::pair<int, Mat>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, kIdentity});
    while (!stack.empty()) {
      auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
        gltf_error("a scene or node names node " + std::to_string(index) + ", which does not exist");
      if (visited_[static_cast<std::size_t>(index)])
        gltf_error("node " + std::to_string(index) + " is reached twice; a scene's nodes form trees");
      visited_[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
      const Mat world = multiply(parent, local_matrix(node));
      if (node.mesh >= 0) add_mesh(node.mesh, world);
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.push_back({*c, world});
    }
    if (mesh_.triangles.empty() && mesh_.segments.empty() && mesh_.points.empty())
      gltf_error("the default scene has no triangles, lines or points to draw");
    if (!textured_) {
      mesh_.textures.clear(), mesh_.uvs.clear(), mesh_.face_textures.clear();
      for (raster::Material& m : mesh_.materials) m.metallic_roughness_texture = -1;
    } else {
      room(mesh_.uvs, mesh_.positions.size() - mesh_.uvs.size(), counts_.vertices);
      mesh_.uvs.resize(mesh_.positions.size(), {0, 0});
      mesh_.uv_triangles = mesh_.triangles;
    }
    // One colour for the whole mesh when every vertex has the same (COLOR_0 of one value).
    if (!one_colour_ && std::all_of(mesh_.colors.begin(), mesh_.colors.end(),
                                    [&](Rgba8 c) { return c == mesh_.colors.front(); }))
      mesh_.colors.erase(mesh_.colors.begin() + 1, mesh_.colors.end());
    if (any_lit_ == false && any_unlit_) mesh_.shading = Shading::unlit;
    finish_normals();
    mesh_.crease_deg = kModelCreaseDeg;  // for a picture that asks for smooth shading
    return std::move(mesh_);
  }

 private:
  void add_mesh(int index, const Mat& m) {
    if (static_cast<std::size_t>(index) >= model_.meshes.size())
      gltf_error("a node names mesh " + std::to_string(index) + ", which does not exist");
    // Normals go through the inverse transpose of the upper 3x3 (a, b, c / d, e, f / g, h, k, by rows): the
    // cofactor matrix, which is det x that, times the sign of det. A mirroring transform turns the winding.
    const double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], k = m[10];
    const double det = a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
    const bool mirrored = det < 0;
    const double sign = mirrored ? -1 : 1;
    const double n[9] = {sign * (e * k - f * h), sign * (f * g - d * k), sign * (d * h - e * g),
                         sign * (c * h - b * k), sign * (a * k - c * g), sign * (b * g - a * h),
                         sign * (b * f - c * e), sign * (c * d - a * f), sign * (a * e - b * d)};
    const auto& primitives = model_.meshes[static_cast<std::size_t>(index)].primitives;
    // Nodes times their meshes' primitives: 150,000 nodes naming one mesh of 150,000 primitives are a few
    // megabytes of text and 2e10 primitives to read.
    drawn_primitives_ += primitives.size();
    if (drawn_primitives_ > kMaxDrawnPrimitives)
      throw SceneError(ErrorKind::limit,
                       "glTF: the default scene draws more than " + std::to_string(kMaxDrawnPrimitives) +
                           " mesh primitives (each node draws every primitive of its mesh)");
    for (std::size_t pi = 0; pi < primitives.size(); ++pi) {
      const tinygltf::Primitive& p = primitives[pi];
      const std::string where = "mesh " + std::to_string(index) + " primitive " + std::to_string(pi);
      // A primitive costs a few microseconds even when empty: kPrimitiveWork units, and its elements below.
      meter_.add(kPrimitiveWork);
      const auto pos_it = p.attributes.find("POSITION");
      if (pos_it == p.attributes.end()) gltf_error(where + " has no POSITION");
      const AccessorView positions(model_, pos_it->second, where + " POSITION");
      if (positions.components() != 3) gltf_error(positions.what() + " is not VEC3");
      const std::size_t base = mesh_.positions.size();
      add_positions(positions, m);
      const std::size_t count = positions.count();
      const bool has_normals = add_normals(p, where, count, n);
      const Material material = material_of(p.material, where);
      add_colours(p, where, count, material.colour, material.blend);
      add_uvs(p, where, count, material);
      primitive_surface_ = material.surface;
      if (material.surface >= 0 && mesh_.face_materials.empty()) {  // the first: earlier faces are Lambert
        room(mesh_.face_materials, mesh_.triangles.size(), counts_.faces);
        mesh_.face_materials.assign(mesh_.triangles.size(), -1);
      }

      // Its faces: straight from a triangle list's indices, else through its corner order.
      const std::size_t first_triangle = mesh_.triangles.size();
      if (p.indices >= 0 && p.mode == TINYGLTF_MODE_TRIANGLES) {  // most meshes: indices are the triangles
        const AccessorView indices(model_, p.indices, where + " indices");
        add_triangles(indices.count() / 3, mirrored, [&](std::array<std::uint32_t, 3>* out) {
          indices.triangles(static_cast<std::uint32_t>(base), count, out);
        });
      } else {
        // The primitive's corner order: its indices, or 0..count-1.
        std::vector<std::uint32_t>& corners = corners_;
        if (p.indices >= 0) {
          AccessorView(model_, p.indices, where + " indices")
              .indices(static_cast<std::uint32_t>(base), count, corners);
        } else {
          corners.resize(count);
          for (std::size_t i = 0; i < count; ++i) corners[i] = static_cast<std::uint32_t>(base + i);
        }
        add_faces(p.mode, corners, mirrored, where);
      }
      if (!has_normals) without_normals_.push_back({first_triangle, mesh_.triangles.size()});
    }
  }

  // The primitive's POSITIONs under its node's transform `m`, appended to mesh_.positions, within the
  // vertex limit and the memory budget; every coordinate checked to be finite and within +-2^128.
  void add_positions(const AccessorView& positions, const Mat& m) {
    const std::size_t base = mesh_.positions.size();
    if (base + positions.count() > 3 * static_cast<std::size_t>(limits_.max_model_faces) + 3)
      throw SceneError(ErrorKind::limit, "the model has more than " +
                                             std::to_string(3 * limits_.max_model_faces) + " vertices");
    // Its loops (positions, normals, colours, uvs: each linear in the accessor) counted before they run.
    meter_.add(4 * positions.count());
    room(mesh_.positions, positions.count(), counts_.vertices);
    mesh_.positions.resize(base + positions.count());
    Vec3f* out = mesh_.positions.data() + base;
    // Every coordinate finite and within +-2^128 (what the renderer takes): checked as it is stored, the
    // first bad one remembered for the error.
    std::size_t bad = SIZE_MAX;
    auto put = [&](std::size_t i, const Vec3& w) {
      const bool ok = (std::fabs(w.x) <= kMaxCoordinate) & (std::fabs(w.y) <= kMaxCoordinate) &
                      (std::fabs(w.z) <= kMaxCoordinate);
      if (!ok && bad == SIZE_MAX) bad = i;
      out[i] = Vec3f(w);
    };
    if (m == kIdentity)  // most nodes: no transform to apply
      positions.each_vec3([&](std::size_t i, double x, double y, double z) { put(i, {x, y, z}); });
    else
      positions.each_vec3([&](std::size_t i, double x, double y, double z) {
        put(i, {m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
                m[2] * x + m[6] * y + m[10] * z + m[14]});
      });
    if (bad != SIZE_MAX)
      gltf_error(positions.what() + " element " + std::to_string(bad) +
                 " is not a finite point within +-2^128 (after its node's transform)");
  }

  // The primitive's NORMALs, turned with its node, after those of earlier primitives (zeros where they had
  // none); false when it has none.
  bool add_normals(const tinygltf::Primitive& p, const std::string& where, std::size_t count,
                   const double* n) {
    const auto it = p.attributes.find("NORMAL");
    if (it == p.attributes.end()) return false;
    const AccessorView normals(model_, it->second, where + " NORMAL");
    if (normals.components() != 3 || normals.count() != count) return false;
    const std::size_t base = mesh_.positions.size() - count;
    room(mesh_.normals, base + count - mesh_.normals.size(), counts_.vertices);
    mesh_.normals.resize(base);
    normals.each_vec3([&](std::size_t, double x, double y, double z) {
      mesh_.normals.push_back(Vec3f(Vec3{n[0] * x + n[1] * y + n[2] * z, n[3] * x + n[4] * y + n[5] * z,
                                         n[6] * x + n[7] * y + n[8] * z}));
    });
    return true;
  }

  // glTF draws a primitive without normals flat. A mesh with none is shaded flat; one where only some
  // primitives have normals gets a face normal for each triangle of the others.
  void finish_normals() {
    if (mesh_.normals.empty()) {
      if (mesh_.shading == Shading::smooth) mesh_.shading = Shading::flat;
      return;
    }
    room(mesh_.normals, mesh_.positions.size() - std::min(mesh_.positions.size(), mesh_.normals.size()),
         counts_.vertices);
    mesh_.normals.resize(mesh_.positions.size());
    room(mesh_.normal_triangles, mesh_.triangles.size(), counts_.faces);
    mesh_.normal_triangles = mesh_.triangles;
    const auto& pos = mesh_.positions;
    for (const auto& [first, end] : without_normals_)
      for (std::size_t t = first; t < end; ++t) {
        meter_.add(1);
        const auto& tri = mesh_.triangles[t];
        const Vec3 a = pos[tri[0]], b = pos[tri[1]], c = pos[tri[2]];
        const Vec3 u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z};
        const auto k = static_cast<std::uint32_t>(mesh_.normals.size());
        mesh_.normals.push_back(
            Vec3f(Vec3{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x}));
        mesh_.normal_triangles[t] = {k, k, k};
      }
  }

  void add_colours(const tinygltf::Primitive& p, const std::string& where, std::size_t count,
                   const std::array<double, 4>& factor, bool blend) {
    const auto it = p.attributes.find("COLOR_0");
    std::optional<AccessorView> colours;
    if (it != p.attributes.end()) {
      colours.emplace(model_, it->second, where + " COLOR_0");
      if ((colours->components() != 3 && colours->components() != 4) || colours->count() != count)
        gltf_error(colours->what() + " is not one VEC3 or VEC4 per vertex");
    }
    // glTF colours are linear; the 8-bit colours lit here are sRGB-encoded, as texels are.
    auto encoded = [](const double* c) -> Rgba8 {
      return {detail::unit_byte(srgb_of_linear(c[0])), detail::unit_byte(srgb_of_linear(c[1])),
              detail::unit_byte(srgb_of_linear(c[2])), detail::unit_byte(c[3])};
    };
    const std::size_t base = mesh_.positions.size() - count;
    if (!colours) {  // one colour for the primitive, encoded once, and stored once while the mesh has one
      const Rgba8 c = encoded(factor.data());
      if (one_colour_ && (base == 0 || mesh_.colors.front() == c)) {
        mesh_.colors.assign(1, c);
        return;
      }
      colour_each_vertex(base);
      mesh_.colors.insert(mesh_.colors.end(), count, c);
      return;
    }
    colour_each_vertex(base);
    room(mesh_.colors, count, counts_.vertices);
    for (std::size_t i = 0; i < count; ++i) {
      double c[4] = {factor[0], factor[1], factor[2], factor[3]};
      for (int k = 0; k < colours->components(); ++k) c[k] *= colours->get(i, k);
      if (!blend) c[3] = 1;  // an opaque material is opaque whatever its vertices' alpha
      mesh_.colors.push_back(encoded(c));
    }
  }

  // From one colour for the mesh to one for each of the `vertices` read so far.
  void colour_each_vertex(std::size_t vertices) {
    if (!one_colour_) return;
    one_colour_ = false;
    if (vertices == 0) return;
    const Rgba8 c = mesh_.colors.front();
    room(mesh_.colors, vertices, counts_.vertices);
    mesh_.colors.assign(vertices, c);
  }

  struct Material {
    std::array<double, 4> colour{0.8, 0.8, 0.8, 1};  ///< linear RGBA: baseColorFactor, or the default grey
    std::int32_t texture = -1;                       ///< index into mesh_.textures, or -1
    int texcoord = 0;                                ///< which TEXCOORD_n the texture reads
    bool blend = false;                              ///< alphaMode BLEND: alpha is kept; else opaque
    /// Index into mesh_.materials, or -1: Lambert (no material, or one that gives none of metallicFactor,
    /// roughnessFactor and metallicRoughnessTexture).
    std::int32_t surface = -1;
    std::int32_t metal_rough_texture = -1;  ///< its metallic-roughness texture in mesh_.textures, or -1
    int metal_rough_texcoord = 0;           ///< which TEXCOORD_n that texture reads
  };

  /// What a material does with its texture's alpha: OPAQUE ignores it, MASK keeps a texel where its alpha
  /// times the factor's reaches alphaCutoff and drops it otherwise, BLEND keeps it.
  struct TexelAlpha {
    enum Mode : std::uint8_t { opaque, mask, blend } mode = opaque;
    double cutoff = 0;  ///< mask: the texel alpha (0..1) at and above which a texel is kept
    friend auto operator<=>(const TexelAlpha&, const TexelAlpha&) = default;
  };

  Material material_of(int index, const std::string& where) {
    Material out;
    if (index < 0) {
      out.colour = {0.6038, 0.6038, 0.6038, 1};  // linear of sRGB 204: the grey OBJ models get
      any_lit_ = true;
      return out;
    }
    if (static_cast<std::size_t>(index) >= model_.materials.size())
      gltf_error(where + " names material " + std::to_string(index) + ", which does not exist");
    const tinygltf::Material& mat = model_.materials[static_cast<std::size_t>(index)];
    const auto& pbr = mat.pbrMetallicRoughness;
    for (std::size_t k = 0; k < 4 && k < pbr.baseColorFactor.size(); ++k)
      out.colour[k] = pbr.baseColorFactor[k];
    out.blend = mat.alphaMode == "BLEND";
    TexelAlpha alpha;
    if (out.blend)
      alpha.mode = TexelAlpha::blend;
    else if (mat.alphaMode == "MASK" && out.colour[3] > 0)
      alpha = {TexelAlpha::mask, mat.alphaCutoff / out.colour[3]};
    if (!out.blend) out.colour[3] = 1;
    (mat.extensions.count("KHR_materials_unlit") ? any_unlit_ : any_lit_) = true;
    if (pbr.baseColorTexture.index >= 0) {
      out.texture = texture_of(pbr.baseColorTexture.index, alpha, where);
      out.texcoord = pbr.baseColorTexture.texCoord;
    }
    surface_of(index, mat, out, where);
    return out;
  }

  // The material's metallic-roughness, when it gives any of it. glTF's defaults (metallic 1, roughness 1)
  // apply to a field left out of a material that gives another; a material that gives none of the three
  // (as most exporters of plain colours write, and as rasterd drew every glTF model before) stays Lambert,
  // so that a model's picture changes only where its file asks for metal or gloss. tinygltf fills in the
  // defaults; its `values` map holds only the fields the document wrote.
  void surface_of(int index, const tinygltf::Material& mat, Material& out, const std::string& where) {
    if (KHR_unlit(mat)) return;
    const auto& pbr = mat.pbrMetallicRoughness;
    const bool given = mat.values.count("metallicFactor") || mat.values.count("roughnessFactor") ||
                       mat.values.count("metallicRoughnessTexture");
    if (!given) return;
    if (pbr.metallicRoughnessTexture.index >= 0) {
      out.metal_rough_texture = texture_of(pbr.metallicRoughnessTexture.index, {}, where);
      out.metal_rough_texcoord = pbr.metallicRoughnessTexture.texCoord;
    }
    const auto [cached, is_new] = surfaces_.try_emplace(index, -1);
    if (!is_new) {
      out.surface = cached->second;
      return;
    }
    raster::Material m;
    m.model = raster::Material::Model::metallic_roughness;
    // Out-of-range factors (the spec says 0..1) are clamped rather than refused: the picture stays close to
    // what the author meant. NaN cannot come from JSON.
    m.metallic = static_cast<float>(std::clamp(pbr.metallicFactor, 0.0, 1.0));
    m.roughness = static_cast<float>(std::clamp(pbr.roughnessFactor, 0.0, 1.0));
    m.metallic_roughness_texture = out.metal_rough_texture;
    cached->second = static_cast<std::int32_t>(mesh_.materials.size());
    mesh_.materials.push_back(m);
    out.surface = cached->second;
  }

  static bool KHR_unlit(const tinygltf::Material& mat) {
    return mat.extensions.count("KHR_materials_unlit") != 0;
  }

  // The texture's index in mesh_.textures, decoded once for each way a material takes its alpha.
  std::int32_t texture_of(int index, TexelAlpha alpha, const std::string& where) {
    if (static_cast<std::size_t>(index) >= model_.textures.size())
      gltf_error(where + "'s material names texture " + std::to_string(index) + ", which does not exist");
    const tinygltf::Texture& t = model_.textures[static_cast<std::size_t>(index)];
    if (t.source < 0) return -1;  // an extension's image (KTX2, WebP) rasterd cannot decode: untextured
    if (static_cast<std::size_t>(t.source) >= model_.images.size())
      gltf_error("texture " + std::to_string(index) + " names image " + std::to_string(t.source) +
                 ", which does not exist");
    const auto [cached, is_new] = textures_.try_emplace({t.source, alpha}, -1);
    if (!is_new) return cached->second;
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(t.source)];
    std::string_view bytes(reinterpret_cast<const char*>(image.image.data()), image.image.size());
    std::string name = image.name.empty() ? "image " + std::to_string(t.source) : image.name;
    if (image.bufferView < 0 && !image.uri.empty() && image.uri.rfind("data:", 0) != 0) {
      const std::string* upload = find_upload(files_, image.uri);
      name = file_name_of_uri(image.uri);
      if (!upload)
        gltf_error("the model asks for image \"" + name +
                   "\", which was not sent; sent: " + upload_names(files_) +
                   ". Send it as a multipart part with that file name (curl -F 'file=@" + name + "')");
      bytes = *upload;
    }
    meter_.check();  // each decoding is bounded by the texel budget; asked before each
    Texture texture = decode_texture(bytes, name, texel_budget_);
    texel_budget_ -= std::int64_t{texture.width} * texture.height;
    if (t.sampler >= 0 && static_cast<std::size_t>(t.sampler) < model_.samplers.size())
      texture.clamp =
          model_.samplers[static_cast<std::size_t>(t.sampler)].wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    if (alpha.mode != TexelAlpha::blend)
      for (std::size_t k = 3; k < texture.rgba.size(); k += 4)
        texture.rgba[k] = alpha.mode == TexelAlpha::opaque || texture.rgba[k] >= alpha.cutoff * 255 ? 255 : 0;
    cached->second = static_cast<std::int32_t>(mesh_.textures.size());
    mesh_.textures.push_back(std::move(texture));
    return cached->second;
  }

  void add_uvs(const tinygltf::Primitive& p, const std::string& where, std::size_t count,
               const Material& material) {
    // Once a primitive is textured, one uv per position and a texture per triangle: (0, 0) and -1 where a
    // primitive has none. Before that, neither is kept.
    // The metallic-roughness texture reads the base colour's coordinates when the material has both (a
    // mesh holds one set of texture coordinates), its own otherwise.
    const std::size_t base = mesh_.positions.size() - count;
    primitive_texture_ = material.texture;
    const int texcoord = material.texture >= 0 ? material.texcoord : material.metal_rough_texcoord;
    const auto it = p.attributes.find("TEXCOORD_" + std::to_string(texcoord));
    if (material.texture >= 0 && it == p.attributes.end()) primitive_texture_ = -1;
    const bool reads_uvs =
        it != p.attributes.end() && (primitive_texture_ >= 0 || material.metal_rough_texture >= 0);
    if (reads_uvs && !textured_) {
      textured_ = true;
      room(mesh_.face_textures, mesh_.triangles.size(), counts_.faces);
      mesh_.face_textures.assign(mesh_.triangles.size(), -1);
    }
    if (textured_) {
      room(mesh_.uvs, mesh_.positions.size() - mesh_.uvs.size(), counts_.vertices);
      mesh_.uvs.resize(mesh_.positions.size(), {0, 0});
    }
    if (!reads_uvs) return;
    const AccessorView uv(model_, it->second, where + " TEXCOORD_" + std::to_string(texcoord));
    if (uv.components() != 2 || uv.count() != count) gltf_error(uv.what() + " is not one VEC2 per vertex");
    for (std::size_t i = 0; i < count; ++i) {
      const double u = uv.get(i, 0), v = uv.get(i, 1);
      if (!(std::fabs(u) <= 1e30 && std::fabs(v) <= 1e30))  // NaN, infinite, or out of a float's range
        gltf_error(uv.what() + " element " + std::to_string(i) + " is not a finite coordinate");
      mesh_.uvs[base + i] = {static_cast<float>(u), static_cast<float>(1 - v)};  // glTF's v runs down
    }
  }

  // Room for `more` elements in `v`, an array of one element per vertex (face) of the model: the first time
  // for every vertex (face) the document draws (check_what_it_builds), asked of the budget once, so no
  // array grows (a growing array is held twice while it moves).
  template <typename T>
  void room(std::vector<T>& v, std::size_t more, std::uint64_t total) {
    if (v.capacity() - v.size() >= more) return;
    const std::size_t capacity = std::max<std::size_t>(v.size() + more, static_cast<std::size_t>(total));
    detail::reserve(limits_, static_cast<std::int64_t>((capacity - v.capacity()) * sizeof(T)),
                    [&] { return "the model's " + std::to_string(capacity) + " vertices or faces"; });
    detail::reserve_huge(v, capacity);
  }

  // `more` triangles to come: refused over the face limit, else room made for them.
  void make_room_for_triangles(std::size_t more) {
    meter_.add(more);  // the triangles' loop, counted before it runs
    if (mesh_.triangles.size() + more > static_cast<std::size_t>(limits_.max_model_faces))
      detail::too_many_faces(limits_.max_model_faces);
    room(mesh_.triangles, more, counts_.faces);
    if (textured_) room(mesh_.face_textures, more, counts_.faces);
    if (!mesh_.materials.empty()) room(mesh_.face_materials, more, counts_.faces);
  }

  // `count` triangles that `fill` writes at once (the common case, in straight loops rather than one call a
  // triangle), wound back where the node mirrors.
  template <typename Fill>
  void add_triangles(std::size_t count, bool mirrored, Fill&& fill) {
    const std::size_t first = mesh_.triangles.size();
    make_room_for_triangles(count);
    mesh_.triangles.resize(first + count);
    std::array<std::uint32_t, 3>* t = mesh_.triangles.data() + first;
    fill(t);
    if (mirrored)
      for (std::size_t i = 0; i < count; ++i) std::swap(t[i][1], t[i][2]);
    if (textured_) mesh_.face_textures.insert(mesh_.face_textures.end(), count, primitive_texture_);
    if (!mesh_.materials.empty())
      mesh_.face_materials.insert(mesh_.face_materials.end(), count, primitive_surface_);
  }

  void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, bool mirrored) {
    mesh_.triangles.push_back(mirrored ? std::array{a, c, b} : std::array{a, b, c});
    if (textured_) mesh_.face_textures.push_back(primitive_texture_);
    if (!mesh_.materials.empty()) mesh_.face_materials.push_back(primitive_surface_);
  }

  void add_faces(int mode, const std::vector<std::uint32_t>& v, bool mirrored, const std::string& where) {
    const std::size_t n = v.size();
    meter_.add(n);
    switch (mode) {
      case TINYGLTF_MODE_TRIANGLES:
        add_triangles(n / 3, mirrored, [&](std::array<std::uint32_t, 3>* t) {
          for (std::size_t i = 0; i < n / 3; ++i) t[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
        });
        break;
      case TINYGLTF_MODE_TRIANGLE_STRIP:  // every other triangle turned back to the strip's winding
        make_room_for_triangles(n < 2 ? 0 : n - 2);
        for (std::size_t i = 0; i + 2 < n; ++i)
          add_triangle(v[i], v[i + 1 + (i & 1)], v[i + 2 - (i & 1)], mirrored);
        break;
      case TINYGLTF_MODE_TRIANGLE_FAN:
        make_room_for_triangles(n < 2 ? 0 : n - 2);
        for (std::size_t i = 1; i + 1 < n; ++i) add_triangle(v[0], v[i], v[i + 1], mirrored);
        break;
      case TINYGLTF_MODE_POINTS:  // each vertex a round point (Mesh::points), unlit
        if (mesh_.points.size() + n > static_cast<std::size_t>(limits_.max_model_points))
          throw SceneError(ErrorKind::limit,
                           "the model has more than " + std::to_string(limits_.max_model_points) + " points");
        room(mesh_.points, n, counts_.vertices);
        mesh_.points.insert(mesh_.points.end(), v.begin(), v.end());
        break;
      case TINYGLTF_MODE_LINE:
        room(mesh_.segments, n / 2, counts_.faces);
        for (std::size_t i = 0; i + 1 < n; i += 2) mesh_.segments.push_back({v[i], v[i + 1]});
        break;
      case TINYGLTF_MODE_LINE_STRIP:
      case TINYGLTF_MODE_LINE_LOOP:
        room(mesh_.segments, n, counts_.faces);
        for (std::size_t i = 0; i + 1 < n; ++i) mesh_.segments.push_back({v[i], v[i + 1]});
        if (mode == TINYGLTF_MODE_LINE_LOOP && n > 2) mesh_.segments.push_back({v[n - 1], v[0]});
        break;
      default:
        gltf_error(where + " has mode " + std::to_string(mode) + ", which glTF does not define");
    }
    if (mesh_.segments.size() > 3 * static_cast<std::size_t>(limits_.max_model_faces))
      throw SceneError(ErrorKind::limit,
                       "the model has more than " + std::to_string(3 * limits_.max_model_faces) + " lines");
  }

  const tinygltf::Model& model_;
  const Limits& limits_;
  const Uploads& files_;
  detail::ReadMeter meter_{limits_};  ///< the deadline, asked as the work adds up
  const std::uint64_t
      sent_;            ///< bytes of the model and its uploads: what it may build (check_what_it_builds)
  BuiltCounts counts_;  ///< what the drawn primitives build: the arrays are sized to it once
  Mesh mesh_;
  std::vector<bool> visited_;
  std::map<std::pair<int, TexelAlpha>, std::int32_t>
      textures_;  ///< (image, alpha) -> index into mesh_.textures
  std::int64_t texel_budget_ = limits_.max_texture_pixels;
  std::int32_t primitive_texture_ = -1;
  std::int32_t primitive_surface_ = -1;   ///< the current primitive's index into mesh_.materials
  std::map<int, std::int32_t> surfaces_;  ///< glTF material -> index into mesh_.materials
  bool any_lit_ = false, any_unlit_ = false;
  /// Triangles [first, end) of the primitives that had no NORMAL, for finish_normals.
  std::vector<std::pair<std::size_t, std::size_t>> without_normals_;
  std::size_t drawn_primitives_ = 0;    ///< primitives of every node's mesh so far, for kMaxDrawnPrimitives
  bool textured_ = false;               ///< a primitive so far had a texture and its coordinates
  bool one_colour_ = true;              ///< every vertex so far has mesh_.colors[0]: it is stored once
  std::vector<std::uint32_t> corners_;  ///< the current primitive's vertex order, kept for its capacity
};

}  // namespace

Mesh build_mesh(const tinygltf::Model& model, const Limits& limits, const Uploads& files,
                std::uint64_t sent) {
  return MeshBuilder(model, limits, files, sent).read();
}

}  // namespace raster::gltf
