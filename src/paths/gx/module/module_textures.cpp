// The module's textures as one embedded TPL (module_textures.h).
#include "paths/gx/module/module_textures.h"

#include <algorithm>

#include "core/error.h"

namespace lt::gx {

namespace {

const std::vector<u8>& plan_array_bytes(const MaterialPlan& m, const std::string& name) {
  const auto a = std::find_if(m.arrays.begin(), m.arrays.end(),
                              [&](const ArrayPlan& x) { return x.name == name; });
  LT_CHECK(a != m.arrays.end(), "the plan has no array " + name);
  return a->bytes;
}

TplTexture planned_tpl_texture(const MaterialPlan& m, const TexturePlan& t) {
  TplTexture out;
  const std::optional<TexFormat> format =
      tex_format_from_number(static_cast<int>(t.format.value()));
  LT_CHECK(format.has_value(), "a planned texture has a GX format");
  out.format = *format;
  out.width = t.width;
  out.height = t.height;
  out.data = plan_array_bytes(m, t.array);
  out.wrap_s = static_cast<u32>(t.wrap_s.value());
  out.wrap_t = static_cast<u32>(t.wrap_t.value());
  // GX_LINEAR both ways, what GX_InitTexObj sets without mipmaps [OGC gx.c L3236]; libogc reads
  // the header's filters only for a mip chain (max LOD > 0) [OGC tpl.c L241-247].
  out.min_filter = out.mag_filter = 1;
  if (t.mip) {
    // A mip chain (:mip=): max LOD = levels - 1 in the header makes TPL_GetTexture call
    // GX_InitTexObj with mipmaps on and GX_InitTexObjLOD with the header's filters and bias
    // [OGC tpl.c L241-250]; the program's own GX_InitTexObjLOD after it sets every field.
    out.levels = t.mip->levels;
    out.min_filter = static_cast<u32>(t.mip->min_filter.value());
    out.lod_bias = t.mip->bias;
    // The header's "edge LOD" byte cannot carry :mip-lod=: libogc passes it to GX_InitTexObjLOD
    // as the max anisotropy and its bias clamp (bias > 0) as the edge LOD flag [OGC tpl.c
    // L242-248, GX_InitTexObjLOD(..., biasclamp, biasclamp, edgelod)]. So it holds the
    // anisotropy the program's own call sets, GX_ANISO_1 (0): a TPL read alone then differs
    // from the module only where libogc derives the flags from the bias.
    out.edge_lod = 0;
  }
  if (t.tlut) {
    out.tlut_format = static_cast<TlutFormat>(t.tlut->format.value());
    const std::vector<u8>& tlut = plan_array_bytes(m, t.tlut->array);
    out.tlut.assign(tlut.begin(), tlut.begin() + 2 * t.tlut->entries);
  }
  return out;
}

std::string tpl_note(int id) {
  return "From texture " + std::to_string(id) + " of " + kModuleTplArray;
}

}  // namespace

ModuleTextures module_textures(const ScenePlan& plan) {
  ModuleTextures out;
  for (const MaterialPlan& m : plan.materials) {
    for (const PassPlan& p : m.passes) {
      for (const TexGenPlan& g : p.texgens) {
        if (!g.texture || out.id.count(g.texture->array)) continue;
        out.id[g.texture->array] = static_cast<int>(out.textures.size());
        out.textures.push_back(planned_tpl_texture(m, *g.texture));
        out.names.push_back(g.texture->array);
        out.arrays.push_back(g.texture->array);
        if (g.texture->tlut) out.arrays.push_back(g.texture->tlut->array);
      }
    }
  }
  return out;
}

Function take_textures_from_tpl(Function f, const ModuleTextures& t) {
  std::vector<Statement> body;
  const Arg tpl = Arg::address_of(kModuleTplFile);
  auto id_of = [&](const std::string& array) {
    const auto it = t.id.find(array);
    LT_CHECK(it != t.id.end(), "the module's TPL has no texture " + array);
    return it->second;
  };
  for (size_t k = 0; k < f.body.size(); ++k) {
    Statement st = f.body[k];
    if (st.kind != Statement::Kind::Call) {
      body.push_back(std::move(st));
      continue;
    }
    const Call& c = st.call;
    if (c.function == "GX_InitTexObj") {
      const int id = id_of(c.args[1].name);
      st.comment += (st.comment.empty() ? "" : "\n") + tpl_note(id) +
                    " (GX_InitTexObj from its header [OGC tpl.c L245])";
      st.call = Call("TPL_GetTexture", {tpl, Arg::literal(id), c.args[0]});
    } else if (c.function == "GX_InitTlutObj") {
      // TPL_GetTextureCI initialises the TLUT object and the texture together [OGC tpl.c
      // L303-304], so it takes the place of the first; the GX_LoadTlut between them stays.
      const auto ci = std::find_if(
          f.body.begin() + static_cast<std::ptrdiff_t>(k), f.body.end(), [](const Statement& s) {
            return s.kind == Statement::Kind::Call && s.call.function == "GX_InitTexObjCI";
          });
      LT_CHECK(ci != f.body.end(), "a TLUT object without its GX_InitTexObjCI");
      const Call& tex = ci->call;
      const int id = id_of(tex.args[1].name);
      st.comment += (st.comment.empty() ? "" : "\n") + ci->comment +
                    (ci->comment.empty() ? "" : "\n") + tpl_note(id) +
                    " (GX_InitTlutObj, GX_InitTexObjCI [OGC tpl.c L303-304])";
      st.call =
          Call("TPL_GetTextureCI", {tpl, Arg::literal(id), tex.args[0], c.args[0], tex.args[8]});
    } else if (c.function == "GX_InitTexObjCI") {
      continue;  // taken by TPL_GetTextureCI above
    }
    body.push_back(std::move(st));
  }
  f.body = std::move(body);
  return f;
}

std::vector<Statement> with_textures_in_tpl(const std::vector<Statement>& top_level,
                                            const ModuleTextures& t) {
  std::vector<Statement> out;
  for (const Statement& s : top_level) {
    const bool replaced =
        s.kind == Statement::Kind::Declaration &&
        s.declaration.type == Declaration::Type::ByteArray &&
        std::find(t.arrays.begin(), t.arrays.end(), s.declaration.name) != t.arrays.end();
    if (!replaced) out.push_back(s);
  }
  if (t.textures.empty()) return out;
  Declaration bytes;
  bytes.type = Declaration::Type::ByteArray;
  bytes.name = kModuleTplArray;
  for (u8 b : write_tpl(t.textures)) bytes.values.push_back(b);
  std::string listing =
      "The module's textures as one TPL file (docs/textures.md \"TPL files\"), opened once by\n"
      "ltrender_flush_textures; by id (what the --format c program names the array):";
  for (size_t k = 0; k < t.textures.size(); ++k) {
    const TplTexture& x = t.textures[k];
    listing +=
        "\n  " + std::to_string(k) + ": " + t.names[k] + ", " + format_info(x.format).name + " " +
        std::to_string(x.width) + "x" + std::to_string(x.height) +
        (x.tlut.empty() ? "" : ", " + std::to_string(x.tlut.size() / 2) + " palette entries");
  }
  out.push_back(Statement::of(bytes, listing));
  Declaration file;
  file.type = Declaration::Type::TplFile;
  file.name = kModuleTplFile;
  out.push_back(Statement::of(file));
  return out;
}

std::string open_textures_function(const ModuleTextures& t) {
  std::string out =
      "\n// Once, before the first draw: the textures' TPL opened, and the texture cache emptied "
      "so "
      "the\n// GPU reads what the CPU wrote. TPL_GetTexture flushes each texture out of the CPU "
      "cache\n// when a pass takes it [OGC tpl.c L244, gc/ogc/cache.h L123-139].\n"
      "void ltrender_flush_textures(void) {\n";
  if (!t.textures.empty())
    out +=
        std::string("  // Opening twice would add the array's address to its pointers again.\n") +
        "  if (" + kModuleTplFile + ".ntextures == 0)\n    TPL_OpenTPLFromMemory(&" +
        kModuleTplFile + ", " + kModuleTplArray + ", sizeof " + kModuleTplArray + ");\n";
  return out + "  GX_InvalidateTexAll();\n}\n";
}

}  // namespace lt::gx
