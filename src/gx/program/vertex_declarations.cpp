#include "gx/program/vertex_declarations.h"

#include <cctype>
#include <iterator>
#include <string_view>

namespace lt::gx::interp {

namespace {

std::string gx_attribute_name(long long attribute) {
  return std::string(GxConst<NameGroup::VtxAttr>::with_value(attribute).name());
}

// A storage key's value is libogc's type name without "GX_", in lower case (GX_S16 -> s16,
// GX_RGB565 -> rgb565: vertex_storage.h), so a declaration reads through the key's one parser.
std::string storage_name(std::string gx_name) {
  std::string s = gx_name.substr(3);
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

size_t storage_key_index(std::string_view key) {
  for (size_t k = 0; k < std::size(kVertexStorageKeys); ++k)
    if (kVertexStorageKeys[k] == key) return k;
  LT_CHECK(false, "not a vertex storage key");
  return 0;
}

}  // namespace

void clear_vertex_inputs(Machine& m) {
  m.state.vertex = VertexDescriptor{};
  m.state.declared.indexed = false;
  m.state.declared.input_at = {};
}

void set_vertex_input(Machine& m) {
  const long long attribute = m.i(0), input = m.i(1);
  if (attribute == kVaClr1) m.fail_arg(0, "the scene has one vertex colour (GX_VA_CLR0)");
  // The :draw= axis sends a vertex one way: every attribute in the stream, or every one an index
  // into its array (GX_INDEX8 or GX_INDEX16 alike: each array gets the index its size needs).
  if (input != 0) {
    const bool indexed = input >= 2;
    for (int a = kVaPos; a <= kVaTex7; ++a) {
      const u8 other = m.state.vertex.type[static_cast<size_t>(a)];
      if (a == attribute || other == 0 || (other >= 2) == indexed) continue;
      m.fail_arg(1, gx_attribute_name(a) + " is sent " + (other >= 2 ? "indexed" : "GX_DIRECT") +
                        ": a vertex sends every attribute alike (all GX_DIRECT, or all "
                        "GX_INDEX8 / GX_INDEX16), as the gx variant's :draw= does");
    }
  }
  m.state.vertex.type[static_cast<size_t>(attribute)] = m.u(1);
  m.state.declared.input_at[static_cast<size_t>(attribute - kVaPos)] = {m.line(), m.column()};
  if (attribute == kVaPos) m.state.declared.indexed = input >= 2;
}

void set_vertex_attribute_format(Machine& m) {
  const long long format = m.i(0), attribute = m.i(1), count = m.i(2), type = m.i(3), frac = m.i(4);
  const bool texcoord = attribute >= kVaTex0 && attribute <= kVaTex7;
  if (attribute == kVaClr1) m.fail_arg(1, "the scene has one vertex colour (GX_VA_CLR0)");
  if (attribute == kVaPos && count != 1)
    m.fail_arg(2, "the scene's positions have three components (GX_POS_XYZ)");
  if (attribute == kVaNrm && count != 0)
    m.fail_arg(2, "the scene sends the normal alone (GX_NRM_XYZ)");
  if (texcoord && count > 1)
    m.fail_arg(2, "a texture coordinate is GX_TEX_S (the CPU's t) or GX_TEX_ST (the mesh's UV)");
  // GX_SetVtxAttrFmt's type argument is one field for both kinds: the colour encodings for
  // GX_VA_CLRn, the component types for the rest [OGC gx.h L93-103].
  // The names overlap in value (GX_S16 is 3, as GX_RGBA4 is), so the name written says which
  // kind the writer meant; a literal number is read as the attribute's kind.
  bool named_component = false, named_colour = false;
  for (int t = 0; t <= static_cast<int>(ColorType::Rgba8); ++t) {
    if (t <= static_cast<int>(ComponentType::F32))
      named_component |= m.text(3) == component_type_name(static_cast<ComponentType>(t));
    named_colour |= m.text(3) == color_type_name(static_cast<ColorType>(t));
  }
  std::string key, value;
  if (attribute == kVaClr0) {
    if (named_component)
      m.fail_arg(3, m.text(3) +
                        " is a component type; GX_VA_CLR0 takes GX_RGB565, GX_RGB8, "
                        "GX_RGBX8, GX_RGBA4, GX_RGBA6 or GX_RGBA8");
    key = "clr";
    value = storage_name(color_type_name(static_cast<ColorType>(type)));
  } else {
    if (named_colour || type > static_cast<long long>(ComponentType::F32))
      m.fail_arg(3, m.text(3) + " is a colour encoding; " + gx_attribute_name(attribute) +
                        " takes GX_U8, GX_S8, GX_U16, GX_S16 or GX_F32");
    const auto t = static_cast<ComponentType>(type);
    key = attribute == kVaPos ? "vtx" : attribute == kVaNrm ? "nrm" : "uv";
    value = storage_name(component_type_name(t));
    if (attribute == kVaNrm) {
      // libogc writes no fraction for a normal [OGC gx.c __SETVCDFMT L2545-2555]: its exponent
      // is the type's (normal_exponent). A frac that is neither 0 nor that exponent expects a
      // scale the console does not apply.
      if (t != ComponentType::F32 && frac != 0 && frac != normal_exponent(t))
        m.fail_arg(4,
                   "a normal's exponent is fixed by its type (GX_S8: 6, GX_S16: 14) and libogc "
                   "writes no fraction for GX_VA_NRM: give 0 or " +
                       std::to_string(normal_exponent(t)));
    } else if (t != ComponentType::F32) {
      // An F32's frac is written to the VAT, and the loader reads a float as it is
      // (vertex_loader.h): the storage key's f32 takes none.
      value += "/" + std::to_string(frac);
    }
  }
  VertexStorage storage = m.state.declared.storage;
  try {
    set_vertex_storage(storage, key, value, "GX_SetVtxAttrFmt");
  } catch (const InputError& e) {
    m.fail_arg(3, e.what_only());
  }
  // The scene draws with GX_VTXFMT0: the other formats are checked, not stored.
  if (format != 0) return;
  if (texcoord)
    m.state.texcoord_formats.kind[static_cast<size_t>(attribute - kVaTex0)] =
        count == 0 ? TexCoordFormats::S : TexCoordFormats::ST;
  DeclaredStorage& declared = m.state.declared;
  const size_t k = storage_key_index(key);
  // The storage key stores every texture coordinate alike (its uv).
  const std::string before = vertex_storage_value(declared.storage, key);
  if (texcoord && declared.storage_at[k][0] != 0 && before != value)
    m.fail_call(gx_attribute_name(attribute) + " stored as " + value + " where line " +
                std::to_string(declared.storage_at[k][0]) + " stores a texture coordinate as " +
                before +
                ": the stored mesh keeps every texture coordinate alike (the storage "
                "key's uv)");
  declared.storage = storage;
  declared.storage_at[k] = {m.line(), m.column()};
}

void set_vertex_array(Machine& m) {
  const long long attribute = m.i(0);
  if (attribute == kVaClr1) m.fail_arg(0, "the scene has one vertex colour (GX_VA_CLR0)");
  // The CP's arrays are numbered from GX_VA_POS (vertex_format.h kArrayPosition).
  const auto n = static_cast<size_t>(attribute - kVaPos);
  m.state.declared.array_stride[n] = static_cast<int>(m.i(2));
  m.state.declared.array_at[n] = {m.line(), m.column()};
}

}  // namespace lt::gx::interp
