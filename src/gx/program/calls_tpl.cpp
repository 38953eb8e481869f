// libogc's TPL calls (tpl.h): a program opens a TPL file, from the disc or from an array it
// holds, and initialises texture (and TLUT) objects from its textures, as libogc does
// [OGC tpl.c L86-309]. The file is read whole and checked by gx/tpl_file.h (every bad header,
// offset or size refused naming the file and the byte offset); what the objects then get is
// what libogc's GX_InitTexObj / GX_InitTlutObj / GX_InitTexObjCI calls give them, so the
// program's own later GX_InitTexObj* calls change them as they would a game's.
#include <filesystem>

#include "core/fs.h"
#include "gx/program/machine.h"
#include "gx/texture_format.h"
#include "gx/texture_lod.h"
#include "gx/tmem.h"
#include "gx/tpl_file.h"

namespace lt::gx::interp {

namespace {

// TPL_OpenTPLFromFile's name is read relative to the program file's folder (on the console it
// is relative to the working directory libfat gives the game; a program file stands for the
// game, its folder for the disc's root).
std::filesystem::path tpl_path(const Machine& m, const std::string& name) {
  const std::filesystem::path p(name);
  return p.is_absolute() ? p : std::filesystem::path(m.program_file()).parent_path() / p;
}

// Texture `id` of the TPL argument 0, or a refusal naming the id and the file.
const TplTexture& texture_of_tpl(Machine& m, const std::string& call) {
  const TplObject& t = m.tpl(0);
  if (!t.open) m.fail_arg(0, m.name(0) + " was never opened (TPL_OpenTPLFromFile or -Memory)");
  const long long id = m.i(1);
  // libogc returns -1 and leaves the texture object as it was [OGC tpl.c L222, L266]: drawing
  // with it would draw whatever it held, so the id is refused.
  if (id < 0 || id >= static_cast<long long>(t.textures.size()))
    m.fail_arg(1, "texture id " + std::to_string(id) + " is past the " +
                      std::to_string(t.textures.size()) + " textures of " + t.source);
  const TplTexture& tex = t.textures[static_cast<size_t>(id)];
  // libogc turns a max LOD above 0 into GX_InitTexObj's mipmap flag [OGC tpl.c L241]; the
  // levels' addresses halve the size, which holds only for powers of two (calls_pixel.cpp).
  const bool power_of_two =
      (tex.width & (tex.width - 1)) == 0 && (tex.height & (tex.height - 1)) == 0;
  if (tex.levels > 1 && !power_of_two)
    m.fail_arg(1, "texture " + std::to_string(id) + " of " + t.source + " is a mip chain of " +
                      std::to_string(tex.width) + "x" + std::to_string(tex.height) +
                      " texels: a mipmapped texture's size must be a power of two");
  if (is_indexed(tex.format) != (call == "TPL_GetTextureCI"))
    m.fail_arg(1, "texture " + std::to_string(id) + " of " + t.source + " is " +
                      format_info(tex.format).name +
                      (is_indexed(tex.format) ? ": a colour-indexed texture needs TPL_GetTextureCI"
                                              : ", which has no palette for TPL_GetTextureCI"));
  return tex;
}

std::string texture_name(Machine& m, long long id) {
  return "texture " + std::to_string(id) + " of " + m.tpl(0).source;
}

// GX_InitTexObj(obj, data, width, height, format, wrap s, wrap t, GX_FALSE) as TPL_GetTexture
// and TPL_GetTextureCI make it [OGC tpl.c L245, L304]: the header's filters count only for a
// mip chain, so the filters are GX_InitTexObj's, linear [OGC gx.c L3236].
void init_from_tpl(Machine& m, size_t object, const TplTexture& tex) {
  const std::string name = texture_name(m, m.i(1));
  m.hold_bytes(name, tex.data);
  TexObject& t = m.tex(object);
  t.array = name;
  t.texture = TextureObject{};
  t.texture.width = tex.width;
  t.texture.height = tex.height;
  t.texture.format = static_cast<u8>(tex.format);
  t.texture.wrap_s = static_cast<u8>(tex.wrap_s);
  t.texture.wrap_t = static_cast<u8>(tex.wrap_t);
  t.texture.linear = true;
  t.initialised = true;
  t.tlut_name = -1;
  if (tex.levels <= 1) return;
  // A mip chain: GX_InitTexObj with mipmaps on, then GX_InitTexObjLOD(min filter, mag filter,
  // min LOD, max LOD, bias, biasclamp, biasclamp, edgelod) [OGC tpl.c L242-248]: libogc passes
  // its biasclamp (lodbias > 0) as the edge LOD flag too and the header's edge LOD byte as the
  // max anisotropy, so a chain without a positive bias gets diagonal LOD.
  const bool bias_clamp = tex.lod_bias > 0.0f;
  t.texture.levels = tex.levels;
  t.texture.lod = libogc_texture_lod(static_cast<int>(tex.min_filter), tex.min_lod,
                                     static_cast<float>(tex.levels - 1), tex.lod_bias, bias_clamp,
                                     bias_clamp, tex.edge_lod);
  t.texture.linear = tex.mag_filter == 1;
}

}  // namespace

void add_tpl_calls(CallTable& table) {
  using K = ParamKind;
  using G = NameGroup;
  table.insert({
      // TPL_OpenTPLFromFile(&tpl, "name") [OGC tpl.c L86-145].
      {"TPL_OpenTPLFromFile",
       {{of(K::TplRef), of(K::String)},
        [](Machine& m) {
          const std::filesystem::path path = tpl_path(m, m.text(1));
          const std::string text = read_input_file(path, InputKind::Image);
          const std::span<const u8> bytes(reinterpret_cast<const u8*>(text.data()), text.size());
          m.tpl(0) = {path.string(), read_tpl(bytes, path.string()), true};
        }}},
      // TPL_OpenTPLFromMemory(&tpl, array, length) [OGC tpl.c L147-187]: libogc reads the array
      // and checks only that the length is not 0; the length may not exceed the array.
      {"TPL_OpenTPLFromMemory",
       {{of(K::TplRef), of(K::ArrayName), integer(G::Number, 1, 1LL << 32)},
        [](Machine& m) {
          const std::vector<u8>& array = m.bytes(1);
          if (static_cast<size_t>(m.i(2)) > array.size())
            m.fail_arg(2, "length " + std::to_string(m.i(2)) + " is past the " +
                              std::to_string(array.size()) + " bytes of " + m.name(1));
          const std::string source = m.program_file() + ":" + m.name(1);
          m.tpl(0) = {source, read_tpl(array, source), true};
        }}},
      // TPL_GetTexture(&tpl, id, &texobj) [OGC tpl.c L210-250].
      {"TPL_GetTexture",
       {{of(K::TplRef), integer(G::Number, -(1LL << 31), (1LL << 31) - 1), of(K::TexRef)},
        [](Machine& m) { init_from_tpl(m, 2, texture_of_tpl(m, "TPL_GetTexture")); }}},
      // TPL_GetTextureCI(&tpl, id, &texobj, &tlutobj, tlut) [OGC tpl.c L252-309]:
      // GX_InitTlutObj(tlutobj, palette, format, entries), then GX_InitTexObjCI(..., tlut). The
      // palette still has to be loaded (GX_LoadTlut) before the texture is.
      {"TPL_GetTextureCI",
       {{of(K::TplRef), integer(G::Number, -(1LL << 31), (1LL << 31) - 1), of(K::TexRef),
         of(K::TlutRef), integer(G::TlutName, 0, kTlutNames - 1)},
        [](Machine& m) {
          const TplTexture& tex = texture_of_tpl(m, "TPL_GetTextureCI");
          const std::string palette = "the palette of " + texture_name(m, m.i(1));
          m.hold_bytes(palette, tex.tlut);
          m.tlut(3) = {palette, static_cast<u8>(tex.tlut_format),
                       static_cast<int>(tex.tlut.size() / 2), true};
          init_from_tpl(m, 2, tex);
          m.tex(2).tlut_name = static_cast<int>(m.i(4));
        }}},
  });
}

}  // namespace lt::gx::interp
