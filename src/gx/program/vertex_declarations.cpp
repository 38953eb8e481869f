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

// Argument `arg`'s attribute, GX_VA_NBT read as GX_VA_NRM: their descriptor field and array are
// one (gx_state.h kVaNbt). 21..24 are GX_POSMTXARRAY .. GX_LIGHTARRAY, the XF's indexed matrix
// and light arrays, no vertex attribute [OGC gx.h GX_POSMTXARRAY .. GX_VA_NBT].
long long declared_attribute(Machine& m, size_t arg) {
  const long long attribute = m.i(arg);
  if (attribute > kVaTex7 && attribute < kVaNbt)
    m.fail_arg(arg, "not a vertex attribute (GX_VA_POS .. GX_VA_TEX7, GX_VA_NBT)");
  return attribute == kVaNbt ? kVaNrm : attribute;
}

}  // namespace

void clear_vertex_inputs(Machine& m) {
  m.state.vertex = VertexDescriptor{};
  m.state.declared.indexed = false;
  m.state.declared.input_at = {};
}

void set_vertex_input(Machine& m) {
  const long long attribute = declared_attribute(m, 0), input = m.i(1);
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
  const long long format = m.i(0), count = m.i(2), type = m.i(3), frac = m.i(4);
  const bool nbt = m.i(1) == kVaNbt;
  const long long attribute = declared_attribute(m, 1);
  const bool texcoord = attribute >= kVaTex0 && attribute <= kVaTex7;
  if (attribute == kVaPos && count != 1)
    m.fail_arg(2, "the scene's positions have three components (GX_POS_XYZ)");
  // libogc writes GX_VA_NRM's format only with GX_NRM_XYZ and GX_VA_NBT's only with GX_NRM_NBT
  // or GX_NRM_NBT3, and silently ignores any other pairing [OGC gx.c __SETVCDFMT L2545-2554]:
  // the console would keep the format it had, so the pairing is refused.
  if (!nbt && attribute == kVaNrm && count != 0)
    m.fail_arg(2,
               "libogc ignores GX_VA_NRM with " + m.text(2) +
                   ": an NBT is GX_SetVtxAttrFmt(fmt, GX_VA_NBT, GX_NRM_NBT or GX_NRM_NBT3, ...)");
  if (nbt && count == 0)
    m.fail_arg(2,
               "libogc ignores GX_VA_NBT with GX_NRM_XYZ: give GX_NRM_NBT or GX_NRM_NBT3 (or "
               "GX_VA_NRM)");
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
  const bool colour = attribute == kVaClr0 || attribute == kVaClr1;
  if (colour) {
    if (named_component)
      m.fail_arg(3, m.text(3) + " is a component type; " + gx_attribute_name(attribute) +
                        " takes GX_RGB565, GX_RGB8, GX_RGBX8, GX_RGBA4, GX_RGBA6 or GX_RGBA8");
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
      // GX_NRM_NBT 1, GX_NRM_NBT3 2. libogc's GX_NRM_NBT leaves NormalIndex3 (VAT A bit 31) as
      // it was, so after a GX_NRM_NBT3 in this format the console still reads three indices
      // [OGC gx.c __SETVCDFMT L2549-2554] (docs/spec/gx-hardware.md §8.2).
      const bool index3_kept =
          m.state.declared.by_format[static_cast<size_t>(format)].storage.normal_vectors ==
          NormalVectors::Nbt3;
      if (nbt) value += count == 2 || index3_kept ? "/nbt3" : "/nbt";
    } else if (t != ComponentType::F32) {
      // An F32's frac is written to the VAT, and the loader reads a float as it is
      // (vertex_loader.h): the storage key's f32 takes none.
      value += "/" + std::to_string(frac);
    }
  }
  // Each format keeps its own declarations, as the CP keeps eight VATs (gx_state.h
  // DeclaredStorage); the one that declares GX_VA_POS is the one the scene draws with.
  DeclaredStorage& declared = m.state.declared;
  FormatDeclarations& mine = declared.by_format[static_cast<size_t>(format)];
  VertexStorage storage = mine.storage;
  try {
    set_vertex_storage(storage, key, value, "GX_SetVtxAttrFmt");
  } catch (const InputError& e) {
    m.fail_arg(3, e.what_only());
  }
  if (texcoord)
    mine.texcoord_kind[static_cast<size_t>(attribute - kVaTex0)] =
        count == 0 ? TexCoordFormats::S : TexCoordFormats::ST;
  const size_t k = storage_key_index(key);
  // The storage key stores every texture coordinate alike (its uv), and both colours alike (its
  // clr: the scene has one vertex colour, which GX_VA_CLR1 sends too, docs/porting-to-the-wii.md
  // "GX_VA_CLR1"); a colour re-declared replaces itself.
  const std::string before = vertex_storage_value(mine.storage, key);
  const auto other_colour = static_cast<size_t>(attribute == kVaClr0 ? 1 : 0);
  if (texcoord && mine.storage_at[k][0] != 0 && before != value)
    m.fail_call(gx_attribute_name(attribute) + " stored as " + value + " where line " +
                std::to_string(mine.storage_at[k][0]) + " stores a texture coordinate as " +
                before +
                ": the stored mesh keeps every texture coordinate alike (the storage "
                "key's uv)");
  if (colour && mine.color_at[other_colour][0] != 0 && before != value)
    m.fail_call(gx_attribute_name(attribute) + " stored as " + value + " where line " +
                std::to_string(mine.color_at[other_colour][0]) + " stores " +
                gx_attribute_name(kVaClr0 + static_cast<int>(other_colour)) + " as " + before +
                ": both send the scene's one vertex colour, stored alike (the storage key's clr)");
  if (colour) mine.color_at[static_cast<size_t>(attribute - kVaClr0)] = {m.line(), m.column()};
  mine.storage = storage;
  mine.storage_at[k] = {m.line(), m.column()};
  if (attribute == kVaPos) {
    if (declared.format_at[0] != 0 && declared.format != format)
      m.fail_arg(0, "GX_VA_POS is declared in GX_VTXFMT" + std::to_string(declared.format) +
                        " at line " + std::to_string(declared.format_at[0]) +
                        ": a program has no GX_Begin, so the format that declares the position "
                        "is the one the scene draws with, and a pass draws with one");
    declared.format = static_cast<int>(format);
    declared.format_at = {m.line(), m.column()};
  }
  // The drawing format's declarations are the pass's storage and texture coordinate kinds.
  const FormatDeclarations& drawn = declared.by_format[static_cast<size_t>(declared.format)];
  declared.storage = drawn.storage;
  declared.storage_at = drawn.storage_at;
  for (size_t n = 0; n < drawn.texcoord_kind.size(); ++n)
    m.state.texcoord_formats.kind[n] = drawn.texcoord_kind[n];
}

void set_vertex_array(Machine& m) {
  const long long attribute = declared_attribute(m, 0);
  // The CP's arrays are numbered from GX_VA_POS (vertex_format.h kArrayPosition).
  const auto n = static_cast<size_t>(attribute - kVaPos);
  m.state.declared.array_stride[n] = static_cast<int>(m.i(2));
  m.state.declared.array_at[n] = {m.line(), m.column()};
}

}  // namespace lt::gx::interp
