// The module's textures travel as one TPL file (paths/gx/module/module_textures.h, issue 47):
// the TPL a module embeds, read back by gx/tpl_file.h's reader, holds every texture the
// emulator loads from the `--format c` program of the same variant (file_programs: each pass's
// GX state after its GX_LoadTexObj), with the very texels, size, format, wraps and palette, and
// nothing else; the module's passes take them with TPL_GetTexture / TPL_GetTextureCI, never
// over a raw array.
#include <gtest/gtest.h>

#include <sstream>

#include "gx/program/pass_programs.h"
#include "gx/tpl_file.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/module/module_exporter.h"
#include "test_util.h"

namespace lt::gx {
namespace {

// The bytes of `static u8 ltrender_textures_tpl[N] ... = { ... };` in the module's text.
std::vector<u8> embedded_tpl(const std::string& module) {
  const auto decl = module.find("u8 ltrender_textures_tpl[");
  EXPECT_NE(decl, std::string::npos) << "the module embeds no TPL";
  if (decl == std::string::npos) return {};
  const auto open = module.find('{', decl), close = module.find('}', decl);
  std::istringstream in(module.substr(open + 1, close - open - 1));
  std::vector<u8> out;
  for (int v; in >> v;) {
    out.push_back(static_cast<u8>(v));
    in.ignore(1);  // the comma
  }
  const auto size_at = decl + std::string("u8 ltrender_textures_tpl[").size();
  EXPECT_EQ(std::to_string(out.size()),
            module.substr(size_at, module.find(']', size_at) - size_at));
  return out;
}

struct Case {
  const char *scene, *variant;
  int textures;  // distinct textures the passes load: the LUT and the map
  const char* get_call;
};

class GxModuleTpl : public ::testing::TestWithParam<Case> {};

TEST_P(GxModuleTpl, HoldsTheTexturesTheEmulatorLoadsByteForByte) {
  const Case& c = GetParam();
  const Scene scene = load_scene(test::source_dir() / c.scene);
  const GxVariant variant = parse_gx_variant(c.variant);
  const std::string module = export_module(scene, variant, c.scene);
  const std::vector<TplTexture> tpl = read_tpl(embedded_tpl(module), "module");
  ASSERT_EQ(tpl.size(), static_cast<size_t>(c.textures));
  std::vector<int> loads(tpl.size(), 0);
  for (const PassProgram& p : file_programs(emit_programs(plan_scene(scene, variant)).file)) {
    for (const std::optional<TextureObject>& t : p.state.textures) {
      if (!t) continue;
      bool found = false;
      for (size_t k = 0; k < tpl.size(); ++k) {
        const TplTexture& x = tpl[k];
        if (static_cast<u8>(x.format) != t->format || x.width != t->width ||
            x.height != t->height || x.data != t->data || x.wrap_s != t->wrap_s ||
            x.wrap_t != t->wrap_t || x.tlut != t->tlut || x.levels != t->levels)
          continue;
        if (!x.tlut.empty()) {
          EXPECT_EQ(static_cast<u8>(x.tlut_format), t->tlut_format);
        }
        // libogc's TPL_GetTexture passes a chain's header "edge LOD" byte to GX_InitTexObjLOD
        // as its max anisotropy [OGC tpl.c L241-248], so a TPL read alone must carry the
        // anisotropy the --format c program's own GX_InitTexObjLOD sets.
        if (x.levels > 1 && t->lod) {
          EXPECT_EQ(x.edge_lod, t->lod->max_aniso) << p.name;
        }
        ++loads[k];
        found = true;
      }
      EXPECT_TRUE(found) << p.name << ": a " << t->width << "x" << t->height
                         << " texture of format " << int(t->format) << " is not in the TPL";
    }
  }
  for (size_t k = 0; k < tpl.size(); ++k)
    EXPECT_GT(loads[k], 0) << "texture " << k << " of the TPL is loaded by no pass";
  EXPECT_NE(module.find(std::string(c.get_call) + "(&ltrender_tpl, "), std::string::npos);
  // GX_InitTexObj( or GX_InitTexObjCI( over a raw array; a mip chain's GX_InitTexObjLOD stays.
  EXPECT_EQ(module.find("  GX_InitTexObj("), std::string::npos) << "a texture over a raw array";
  EXPECT_EQ(module.find("  GX_InitTexObjCI("), std::string::npos) << "a texture over a raw array";
  EXPECT_NE(module.find("TPL_OpenTPLFromMemory(&ltrender_tpl, ltrender_textures_tpl, sizeof "
                        "ltrender_textures_tpl)"),
            std::string::npos);
}

// A colour-indexed map (CI4, IA8 palette), a CMPR one and an I4 one, each with the I8 LUT.
const Case kCases[] = {
    {"scenes/maps/sphere_map.json", "t=vertex:map=ci4", 2, "TPL_GetTextureCI"},
    {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=cmpr", 2, "TPL_GetTexture"},
    {"scenes/maps/sphere_map.json", "t=vertex:map=i4", 2, "TPL_GetTexture"},
    // The power LUT as I4 (:lut-format=).
    {"scenes/maps/sphere_map.json", "t=vertex:map=i4:lut-format=i4", 2, "TPL_GetTexture"},
    // A mip chain: the TPL holds every level (max LOD = levels - 1), the texels of each.
    {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=cmpr:mip=lin:mip-bias=1.5", 2,
     "TPL_GetTexture"},
};

INSTANTIATE_TEST_SUITE_P(Maps, GxModuleTpl, ::testing::ValuesIn(kCases), [](const auto& info) {
  return test::test_param_name(std::string(info.param.scene) + "_" + info.param.variant);
});

}  // namespace
}  // namespace lt::gx
