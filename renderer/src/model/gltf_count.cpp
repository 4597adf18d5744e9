// What a glTF document's nodes would build, counted from its accessors before anything is built
// (gltf_document.h: check_what_it_builds), apart from the builder so that gltf_mesh.cpp stays one concern.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "model/gltf_document.h"

namespace raster::gltf {

BuiltCounts check_what_it_builds(const tinygltf::Model& model, const std::vector<int>& roots, bool every_mesh,
                                 std::uint64_t sent, std::size_t max_primitives) {
  // A declared count, where its buffer view could hold that many elements (else 0: AccessorView refuses
  // the accessor, naming it, when the walk reaches it); at most 2^32, so a million primitives' sum cannot
  // overflow.
  auto count_of = [&](int accessor) -> std::uint64_t {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size()) return 0;
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) return 0;
    const int component = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType)),
              components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (component <= 0 || components <= 0) return 0;
    const std::uint64_t view = model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteLength;
    const auto size = static_cast<std::uint64_t>(component) * static_cast<std::uint64_t>(components);
    return a.count <= view / size ? std::min<std::uint64_t>(a.count, 1ull << 32) : 0;
  };
  std::uint64_t vertices = 0, faces = 0, primitives = 0;
  auto add = [&](int mesh) {
    if (mesh < 0 || static_cast<std::size_t>(mesh) >= model.meshes.size()) return;
    for (const tinygltf::Primitive& p : model.meshes[static_cast<std::size_t>(mesh)].primitives) {
      ++primitives;
      const auto pos = p.attributes.find("POSITION");
      if (pos == p.attributes.end()) continue;
      const std::uint64_t v = count_of(pos->second), n = p.indices >= 0 ? count_of(p.indices) : v;
      vertices += v;  // POINTS build their vertices and nothing else
      // Faces and segments as add_faces makes them.
      if (p.mode == TINYGLTF_MODE_TRIANGLES) faces += n / 3;
      if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP || p.mode == TINYGLTF_MODE_TRIANGLE_FAN)
        faces += n < 2 ? 0 : n - 2;
      if (p.mode == TINYGLTF_MODE_LINE) faces += n / 2;
      if (p.mode == TINYGLTF_MODE_LINE_STRIP || p.mode == TINYGLTF_MODE_LINE_LOOP)
        faces += n < 2 ? 0 : n - 1 + (p.mode == TINYGLTF_MODE_LINE_LOOP && n > 2);
    }
  };
  if (every_mesh) {
    for (std::size_t i = 0; i < model.meshes.size(); ++i) add(static_cast<int>(i));
  } else {
    std::vector<bool> seen(model.nodes.size(), false);
    std::vector<int> stack(roots.rbegin(), roots.rend());
    // Stops past max_primitives, which is refused below.
    while (!stack.empty() && primitives <= max_primitives) {
      const int index = stack.back();
      stack.pop_back();
      if (index < 0 || static_cast<std::size_t>(index) >= seen.size() ||
          seen[static_cast<std::size_t>(index)])
        continue;
      seen[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
      add(node.mesh);
      stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
    }
  }
  // Every primitive is drawn (POINTS too): a document of many nodes naming a mesh of many primitives is
  // refused before the first is read.
  if (primitives > max_primitives)
    throw SceneError(ErrorKind::limit, "glTF: the default scene draws more than " +
                                           std::to_string(max_primitives) +
                                           " mesh primitives (each node draws every primitive of its mesh)");
  const std::uint64_t allowed = std::max(kModelBuiltFloor, kModelBuiltPerByte * sent);
  auto refuse = [&](std::uint64_t n, const char* what) {
    throw SceneError(ErrorKind::limit,
                     "glTF: the model would build " + std::to_string(n) + " " + what + " from " +
                         std::to_string(sent) + " bytes; at most " + std::to_string(kModelBuiltPerByte) +
                         " per byte sent (or " + std::to_string(kModelBuiltFloor) +
                         " for any model). Its nodes draw its meshes more often than its bytes allow");
  };
  if (vertices > allowed) refuse(vertices, "vertices");
  if (faces > allowed) refuse(faces, "triangles and lines");
  return {vertices, faces};
}

}  // namespace raster::gltf
