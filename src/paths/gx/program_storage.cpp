#include "paths/gx/program_storage.h"

#include <algorithm>
#include <iterator>
#include <optional>

#include "core/error.h"
#include "gx/fifo/cp_registers.h"
#include "paths/gx/object_draw.h"
#include "paths/gx/scene_vertices.h"

namespace lt::gx {

namespace {

std::string source_at(const DeclaredStorage::At& pos) {
  return std::to_string(pos[0]) + ":" + std::to_string(pos[1]);
}

// What the frame's passes declare, merged: each attribute's storage and where, and whether the
// position is indexed. Differing passes are refused.
struct FileDeclarations {
  VertexStorage storage;
  std::array<DeclaredStorage::At, 4> storage_at{};
  std::optional<bool> indexed;
  DeclaredStorage::At input_at{};
  int format = 0;                   // GX_VTXFMTn the passes draw with
  DeclaredStorage::At format_at{};  // where a pass declared it (line 0: none did)
};

FileDeclarations merged_declarations(const Scene& scene, const ScenePrograms& programs) {
  const std::string& file = programs.file.file;
  FileDeclarations out;
  for (const MaterialDraw& d : programs.draws(scene)) {
    const DeclaredStorage& st =
        programs.by_material[d.material][static_cast<size_t>(d.pass)].state.declared;
    for (size_t k = 0; k < std::size(kVertexStorageKeys); ++k) {
      if (st.storage_at[k][0] == 0) continue;
      const std::string_view key = kVertexStorageKeys[k];
      const std::string value = vertex_storage_value(st.storage, key);
      if (out.storage_at[k][0] == 0) {
        set_vertex_storage(out.storage, key, value, file);
        out.storage_at[k] = st.storage_at[k];
      } else if (vertex_storage_value(out.storage, key) != value) {
        throw InputError(file, source_at(st.storage_at[k]),
                         "GX_SetVtxAttrFmt: " + std::string(key) + "=" + value + " where line " +
                             std::to_string(out.storage_at[k][0]) + " stores it as " +
                             vertex_storage_value(out.storage, key) +
                             ": the scene's mesh is stored once a frame, alike in every pass");
      }
    }
    if (st.format_at[0] != 0) {
      if (out.format_at[0] == 0) {
        out.format = st.format;
        out.format_at = st.format_at;
      } else if (out.format != st.format) {
        throw InputError(file, source_at(st.format_at),
                         "GX_SetVtxAttrFmt: GX_VA_POS in GX_VTXFMT" + std::to_string(st.format) +
                             " where line " + std::to_string(out.format_at[0]) +
                             " declares it in GX_VTXFMT" + std::to_string(out.format) +
                             ": the scene's draws use one vertex format, alike in every pass");
      }
    }
    if (st.input_at[kArrayPosition][0] == 0) continue;
    if (!out.indexed) {
      out.indexed = st.indexed;
      out.input_at = st.input_at[kArrayPosition];
    } else if (*out.indexed != st.indexed) {
      throw InputError(file, source_at(st.input_at[kArrayPosition]),
                       "GX_SetVtxDesc: GX_VA_POS sent " +
                           std::string(st.indexed ? "indexed" : "GX_DIRECT") + " where line " +
                           std::to_string(out.input_at[0]) +
                           " sends it otherwise: every pass sends the mesh alike");
    }
  }
  return out;
}

// Bytes one element of array `n` (vertex_format.h's numbering) takes stored as `storage` in a
// pass that reads its texture coordinates as `formats`: the scene's arrays are packed.
int stored_element_bytes(size_t n, const VertexStorage& storage, const TexCoordFormats& formats) {
  if (n == kArrayPosition) return 3 * component_bytes(storage.position.type);
  if (n == kArrayNormal)  // an NBT element is three vectors (GX_VA_NBT shares the array)
    return (storage.normal_vectors == NormalVectors::Normal ? 3 : 9) *
           component_bytes(storage.normal);
  if (n == kArrayColor0 || n == kArrayColor0 + 1) return color_bytes(storage.color);
  const int t = static_cast<int>(n) - kArrayTexCoord0;
  return (formats.is_uv(t) ? 2 : 1) * component_bytes(storage.texcoord.type);
}

// Each GX_SetArray's stride against the element the storage stores there.
void check_array_strides(const Scene& scene, const ScenePrograms& programs,
                         const VertexStorage& storage) {
  for (const MaterialDraw& d : programs.draws(scene)) {
    const GxState& st = programs.by_material[d.material][static_cast<size_t>(d.pass)].state;
    for (size_t n = 0; n < st.declared.array_stride.size(); ++n) {
      if (st.declared.array_at[n][0] == 0) continue;
      const int need = stored_element_bytes(n, storage, st.texcoord_formats);
      // vtx, nrm, clr (both colours' arrays), uv (the texture coordinates').
      const std::string_view key = kVertexStorageKeys[std::min<size_t>(n, 3) - (n == 3 ? 1 : 0)];
      if (st.declared.array_stride[n] != need)
        throw InputError(programs.file.file, source_at(st.declared.array_at[n]),
                         "GX_SetArray: stride " + std::to_string(st.declared.array_stride[n]) +
                             " where " + attribute_name(static_cast<int>(n)) + " stored as " +
                             vertex_storage_value(storage, key) + " takes " + std::to_string(need) +
                             " bytes an element (the scene's arrays are packed)");
    }
  }
}

// A GX_INDEX8 the file declares for an array of more than 255 elements: on the console its
// indices would wrap (and 0xFF drops the vertex), so it is refused where the variant's draw would
// quietly index it with GX_INDEX16 (vertex_quantiser.h index_attributes picks by size).
void check_index8_arrays(const Scene& scene, const ScenePrograms& programs, const GxVariant& v) {
  const bool stored = !v.storage.is_default();
  const SceneView view = SceneView::of(scene);
  for (const MaterialDraw& d : programs.draws(scene)) {
    const GxState& st = programs.by_material[d.material][static_cast<size_t>(d.pass)].state;
    bool any_index8 = false;
    for (u8 input : st.vertex.type) any_index8 |= input == static_cast<u8>(AttributeInput::Index8);
    if (!any_index8) continue;
    for (size_t object : d.objects) {
      const SceneObject& o = scene.objects[object];
      const VertexStream stream = make_vertex_stream(scene, o, view);
      const ObjectSpaceMesh mesh = stored ? object_space_mesh(o, view) : ObjectSpaceMesh{};
      const VertexAttributeData data =
          pass_vertex_data(stored ? mesh.position : stream.position,
                           stored ? mesh.normal : stream.normal, stream, fifo::sent_attributes(st),
                           fifo::sent_formats(st.texcoord_formats), static_cast<size_t>(d.pass));
      const VertexAttributeFormat format = storage_format(v.storage, data, programs.file.file);
      const IndexedArrays arrays =
          index_attributes(quantise_attributes(data, format), programs.file.file);
      for (int n : arrays.arrays) {
        const auto i = static_cast<size_t>(n);
        if (st.vertex.type[i + kVaPos] != static_cast<u8>(AttributeInput::Index8) ||
            arrays.input[i] != AttributeInput::Index16)
          continue;
        throw InputError(
            programs.file.file, source_at(st.declared.input_at[i]),
            "GX_SetVtxDesc: GX_INDEX8 indexes at most 255 elements; " + attribute_name(n) +
                "'s array holds " + std::to_string(arrays.bytes[i].size() / arrays.stride[i]) +
                " elements for " + o.mesh_path.filename().string() + " (declare GX_INDEX16)");
      }
    }
  }
}

GxVariant declared_variant(const Scene& scene, const GxVariant& given,
                           const ScenePrograms& programs) {
  if (programs.source == "generated") return given;
  const std::string& file = programs.file.file;
  const FileDeclarations declared = merged_declarations(scene, programs);
  GxVariant v = given;
  const VertexStorage f32;
  for (size_t k = 0; k < std::size(kVertexStorageKeys); ++k) {
    if (declared.storage_at[k][0] == 0) continue;
    const std::string_view key = kVertexStorageKeys[k];
    const std::string mine = vertex_storage_value(declared.storage, key),
                      axis = vertex_storage_value(given.storage, key);
    if (axis != vertex_storage_value(f32, key) && axis != mine)
      throw InputError("--variant", to_string(given),
                       "gx: :" + std::string(key) + "=" + axis + " where " + file + ":" +
                           source_at(declared.storage_at[k]) + " declares " + mine +
                           " (store an attribute in one place: drop the axis or the declaration)");
    set_vertex_storage(v.storage, key, mine, file);
  }
  if (declared.format_at[0] != 0) {
    if (given.vat != 0 && given.vat != declared.format)
      throw InputError("--variant", to_string(given),
                       "gx: :vat=" + std::to_string(given.vat) + " where " + file + ":" +
                           source_at(declared.format_at) + " draws with GX_VTXFMT" +
                           std::to_string(declared.format) +
                           " (name the format in one place: drop the axis or the declaration)");
    v.vat = declared.format;
  }
  if (declared.indexed) {
    if (*declared.indexed && v.draw == GxVariant::Draw::Direct) v.draw = GxVariant::Draw::Indexed;
    if (!*declared.indexed && v.draw != GxVariant::Draw::Direct)
      throw InputError("--variant", to_string(given),
                       "gx: :draw= sends indices where " + file + ":" +
                           source_at(declared.input_at) +
                           " sends GX_VA_POS GX_DIRECT (declare GX_INDEX8 or GX_INDEX16)");
  }
  check_array_strides(scene, programs, v.storage);
  if (v == given) return v;
  // What the variant axes refuse for a stored mesh, the declarations refuse too.
  const std::string why = refusal(scene, v);
  if (!why.empty() && refusal(scene, given).empty())
    throw InputError(file, "", "the declared vertex storage: " + why);
  // A fraction the mesh overflows: vertex_storage's message at the declaration's line.
  if (!v.storage.is_default()) {
    const SceneView view = SceneView::of(scene);
    for (const SceneObject& o : scene.objects) {
      try {
        (void)stored_vertex_stream(scene, o, view, v.storage, file, draws_indexed(v.draw));
      } catch (const InputError& e) {
        for (size_t k = 0; k < std::size(kVertexStorageKeys); ++k) {
          if (e.where() == kVertexStorageKeys[k] && declared.storage_at[k][0] != 0)
            throw InputError(file, source_at(declared.storage_at[k]),
                             "GX_SetVtxAttrFmt: " + e.what_only());
        }
        throw InputError("--variant", to_string(given), "gx: " + e.where() + ": " + e.what_only());
      }
    }
  }
  if (declared.indexed && *declared.indexed) check_index8_arrays(scene, programs, v);
  return v;
}

}  // namespace

void apply_program_declarations(const Scene& scene, const GxVariant& given,
                                ScenePrograms& programs) {
  programs.variant = declared_variant(scene, given, programs);
  // Indexing is the variant's :draw= now: each pass's descriptor sends its attributes as the
  // generated programs' do (GX_DIRECT), and the draw gives each the index its array needs, so
  // the FIFO log is the variant's to the byte.
  for (auto& passes : programs.by_material)
    for (PassProgram& p : passes)
      for (u8& input : p.state.vertex.type)
        if (input >= static_cast<u8>(AttributeInput::Index8))
          input = static_cast<u8>(AttributeInput::Direct);
}

}  // namespace lt::gx
