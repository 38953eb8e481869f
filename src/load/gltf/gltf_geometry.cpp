#include "load/gltf/gltf_geometry.h"

#include <cmath>

#include "load/gltf/gltf_accessor.h"
#include "load/gltf/gltf_importer.h"
#include "load/gltf/gltf_textures.h"
#include "load/gltf/gltf_topology.h"
#include "scene/scene_limits.h"

namespace lt::gltf {

namespace {

// The attributes the importer reads; any other (TANGENT, another TEXCOORD_n, JOINTS_0, ...) is
// listed as ignored.
bool is_read_attribute(const std::string& name, const std::string& uv_name) {
  return name == "POSITION" || name == "NORMAL" || name == "COLOR_0" || name == uv_name;
}

}  // namespace

TriangleMesh load_primitive(const Document& doc, const PrimitiveDescription& d, const Material& mat,
                            std::size_t& vertices, Notes& notes) {
  const TextureCoordinates& uv_source = d.material.uv;
  const std::string ptr =
      "/meshes/" + std::to_string(d.mesh) + "/primitives/" + std::to_string(d.primitive);
  const tinygltf::Primitive& prim = doc.model.meshes[static_cast<std::size_t>(d.mesh)]
                                        .primitives[static_cast<std::size_t>(d.primitive)];
  // §3.7.2.1: mode defaults to 4 (TRIANGLES); strips and fans become triangle lists, the one
  // topology the paths draw. Points and lines are the importer's to skip (carries_surface).
  if (!carries_surface(prim.mode)) {
    doc.fail(ptr + "/mode", std::string("primitive mode ") + std::to_string(prim.mode) + " (" +
                                mode_name(prim.mode) +
                                ") carries no surface: TRIANGLES, TRIANGLE_STRIP or "
                                "TRIANGLE_FAN (4, 5, 6) are drawn");
  }
  TriangleMesh mesh;
  auto attribute = [&](const char* name) {
    auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
  };
  const int position = attribute("POSITION");
  if (position < 0) doc.fail(ptr + "/attributes", "no POSITION attribute");
  const AccessorValues p = read_accessor(doc, position, "POSITION", {3});
  mesh.positions.resize(p.count());
  for (std::size_t v = 0; v < p.count(); ++v) {
    for (int c = 0; c < 3; ++c) {
      const double x = p.values[v * 3 + c];
      if (!std::isfinite(x) || std::abs(x) > kMaxCoordinate) {
        doc.fail(accessor_pointer(position),
                 "POSITION of vertex " + std::to_string(v) + " is " + std::to_string(x) +
                     (std::isfinite(x) ? ", beyond the coordinate limit 1e9" : " (not finite)"));
      }
      mesh.positions[v][c] = x;
    }
  }
  const std::size_t n = mesh.positions.size();
  auto same_count = [&](const AccessorValues& a, int index, const char* name) {
    if (a.count() != n) {
      doc.fail(accessor_pointer(index), std::string(name) + " has " + std::to_string(a.count()) +
                                            " elements, POSITION " + std::to_string(n));
    }
  };

  if (prim.indices >= 0 && static_cast<std::size_t>(prim.indices) < doc.model.accessors.size()) {
    const tinygltf::Accessor& ia = doc.model.accessors[static_cast<std::size_t>(prim.indices)];
    // §3.7.2.1: indices are UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT scalars, never
    // normalised.
    if (ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      doc.fail(accessor_pointer(prim.indices) + "/componentType",
               "indices must be unsigned integers (5121, 5123, 5125)");
    }
  }
  std::vector<std::uint32_t> indices;
  if (prim.indices >= 0) {
    const AccessorValues idx = read_accessor(doc, prim.indices, "indices", {1});
    indices.reserve(idx.values.size());
    for (std::size_t i = 0; i < idx.values.size(); ++i) {
      if (idx.values[i] >= static_cast<double>(n)) {
        doc.fail(accessor_pointer(prim.indices),
                 "index " + std::to_string(i) + " is " +
                     std::to_string(static_cast<long long>(idx.values[i])) +
                     ", the primitive has " + std::to_string(n) + " vertices");
      }
      indices.push_back(static_cast<std::uint32_t>(idx.values[i]));
    }
  } else {
    // §3.7.2.1: without indices, vertices are drawn in order.
    for (std::size_t v = 0; v < n; ++v) indices.push_back(static_cast<std::uint32_t>(v));
  }
  auto triangles = assemble_triangles(prim.mode, indices);
  if (!triangles) doc.fail(ptr, count_mismatch(prim.mode, indices.size(), prim.indices >= 0));
  mesh.triangles = std::move(*triangles);
  notes.push_back("mapped " + ptr + ": " + std::to_string(mesh.triangles.size()) + " triangles" +
                  (prim.mode == TINYGLTF_MODE_TRIANGLES
                       ? std::string()
                       : std::string(" (from a ") + mode_name(prim.mode) + ")") +
                  ", " + std::to_string(n) + " vertices" +
                  (prim.indices >= 0 ? ", indexed" : ", not indexed"));

  // NORMAL: unit vectors by §3.7.2.1; anything not finite or of zero length is recomputed, as
  // the mesh reader does.
  const int normal = attribute("NORMAL");
  bool normals_usable = normal >= 0;
  if (normal >= 0) {
    const AccessorValues a = read_accessor(doc, normal, "NORMAL", {3});
    same_count(a, normal, "NORMAL");
    mesh.normals.resize(n);
    for (std::size_t v = 0; v < n && normals_usable; ++v) {
      const glm::dvec3 w(a.values[v * 3], a.values[v * 3 + 1], a.values[v * 3 + 2]);
      const double len = glm::length(w);
      normals_usable = std::isfinite(len) && len > 0;
      if (normals_usable) mesh.normals[v] = w / len;
    }
  }
  if (!normals_usable) {
    compute_area_weighted_normals(mesh);
    notes.push_back("computed " + ptr + "/attributes/NORMAL: " +
                    std::string(normal >= 0 ? "not finite or zero somewhere" : "absent") +
                    ", computed from the triangles (area-weighted)");
  }

  // COLOR_0: vec3 or vec4, float or normalised u8/u16 (§3.7.2.1); alpha is not part of the term.
  const int color = attribute("COLOR_0");
  if (color >= 0) {
    const AccessorValues a = read_accessor(doc, color, "COLOR_0", {3, 4});
    same_count(a, color, "COLOR_0");
    mesh.colors.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
      for (int c = 0; c < 3; ++c) mesh.colors[v][c] = a.values[v * a.components + c];
    }
  }
  const std::string uv_name = "TEXCOORD_" + std::to_string(uv_source.set);
  const int uv = attribute(uv_name.c_str());
  if (uv >= 0) {
    const AccessorValues a = read_accessor(doc, uv, uv_name.c_str(), {2});
    same_count(a, uv, uv_name.c_str());
    mesh.uvs.resize(n);
    // glTF's UV origin is the image's top-left (glTF 2.0 §3.8.4.3: v grows downwards);
    // TriangleMesh::uvs follow OpenGL (v = 0 at the bottom row, model/texture_sampling.h), as
    // OBJ's vt and the UV baker do: v flips here, once, after a KHR_texture_transform.
    for (std::size_t v = 0; v < n; ++v)
      mesh.uvs[v] = importer_uv(uv_source, {a.values[v * 2], a.values[v * 2 + 1]});
    notes.push_back("kept " + ptr + "/attributes/" + uv_name +
                    " (for maps; v flipped to OpenGL's bottom-up convention" +
                    (uv_source.transform ? ", after the material's KHR_texture_transform" : "") +
                    ")");
  }
  for (const auto& [name, index] : prim.attributes) {
    if (!is_read_attribute(name, uv_name)) {
      notes.push_back("ignored " + ptr + "/attributes/" + name + ": not part of the term");
    }
  }
  note_unmapped_keys(at_pointer(doc.json, ptr), ptr, {"attributes", "indices", "material", "mode"},
                     "not part of the term (targets: morph targets are not animated)", notes);
  vertices += n;
  if (vertices > kMaxSceneVertices)
    doc.fail(ptr, over_limit_message(vertices, "vertices", kMaxSceneVertices));
  if (mat.translucency && mat.translucency->thickness_source == ThicknessSource::Vertex) {
    if (!mesh.has_colors())
      doc.fail(ptr, "material \"" + mat.name +
                        "\" takes its thickness from COLOR_0, which this primitive lacks");
    check_vertex_thickness(mesh, doc.path.string(), ptr + "/attributes/COLOR_0", "the primitive");
  } else if (mesh.has_colors()) {
    notes.push_back("ignored " + ptr +
                    "/attributes/COLOR_0 as base colour: read and kept, the thickness only with "
                    "extras.ltrender.thickness \"vertex\"");
  }
  check_uvs_for_material(mesh, mat, doc.path.string(), ptr, "the primitive");
  transform_to_world(mesh, d.world);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    check_world_point(doc, d.node_ptr, mesh.positions[v],
                      "vertex " + std::to_string(v) + " of " + ptr);
  return mesh;
}

}  // namespace lt::gltf
