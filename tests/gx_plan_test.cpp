// The gx generator's plan against its program: the plan (pass_plan.h) is the typed source of
// truth; the emitted C, printed, parsed and run by the interpreter, is an independent reading of
// it. Every field the plan states must be what the interpreter's GX state holds, on every demo
// scene and every variant the scene accepts. And material names that collide as C identifiers
// get unique ones that the program reader maps back to the right material.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <bit>

#include "core/error.h"
#include "gx/program/interpreter.h"
#include "gx/program/parser.h"
#include "gx/program/printer.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/scene_pass_programs.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::gx {
namespace {

// GX_COLOR0A0 (4) and GX_COLOR1A1 (5) -> the channel's index [OGC gx.h L3003-3011].
size_t channel_of(long long c) {
  return c == 5 || c == 1 || c == 3 ? 1 : 0;
}

void expect_vertex_format(const VertexFormatPlan& v, const GxState& st, const std::string& at) {
  int expected = 2;  // position, normal
  EXPECT_TRUE(st.vertex.has(kVaPos) && st.vertex.has(kVaNrm)) << at;
  EXPECT_EQ(st.vertex.has(kVaClr0), v.colour) << at;
  expected += v.colour;
  if (v.t) EXPECT_EQ(st.texcoord_formats.kind[0], TexCoordFormats::S) << at;
  if (v.uv) {
    EXPECT_TRUE(st.vertex.has(kVaTex0 + v.uv_attribute())) << at;
    EXPECT_EQ(st.texcoord_formats.kind[static_cast<size_t>(v.uv_attribute())], TexCoordFormats::ST)
        << at;
  }
  expected += v.t + v.uv;
  EXPECT_EQ(st.vertex.count(), expected) << at;
}

void expect_lights(const PassPlan& p, const GxState& st, const std::string& at) {
  for (const LightObjectPlan& o : p.lights) {
    const auto slot = static_cast<size_t>(std::countr_zero(static_cast<unsigned>(o.slot.value())));
    const XfLight& x = st.lighting.lights[slot];
    const std::string where = at + " " + o.name;
    EXPECT_EQ(x.color, o.color) << where;
    EXPECT_EQ(x.position, o.position) << where;
    EXPECT_EQ(x.direction, -o.direction_arg) << where << " (GX_InitLightDir stores -dir)";
    EXPECT_EQ(x.k, o.k) << where;
    // Spot off leaves a = (1, 0, 0) [OGC gx.c GX_InitLightSpot]: the plan's default for a
    // distance light, the fit's numerator for the specular one.
    EXPECT_EQ(x.a, o.a) << where;
  }
}

void expect_channels(const PassPlan& p, const GxState& st, const std::string& at) {
  EXPECT_EQ(st.lighting.num_channels, static_cast<int>(p.channels.size())) << at;
  for (const ChannelPlan& c : p.channels) {
    const size_t i = channel_of(c.channel.value());
    for (size_t ctl : {i, i + 2}) {  // GX_COLORnAn sets the colour and the alpha control
      const ChannelControl& s = st.lighting.control[ctl];
      const std::string where = at + " " + c.channel.name() + " control " + std::to_string(ctl);
      EXPECT_EQ(s.lighting, c.enable.value() != 0) << where;
      EXPECT_EQ(s.ambient_source, c.ambient_source.value()) << where;
      EXPECT_EQ(s.material_source, c.material_source.value()) << where;
      EXPECT_EQ(s.light_mask, c.lights.bits) << where;
      EXPECT_EQ(s.diffuse_fn, c.diffuse_fn.value()) << where;
      EXPECT_EQ(s.attenuation_fn, c.attenuation_fn.value()) << where;
    }
    if (c.ambient) EXPECT_EQ(st.lighting.ambient[i], *c.ambient) << at;
    if (c.material) EXPECT_EQ(st.lighting.material[i], *c.material) << at;
  }
}

const ArrayPlan* array_named(const MaterialPlan& m, const std::string& name) {
  for (const ArrayPlan& a : m.arrays) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

void expect_texgens(const MaterialPlan& m, const PassPlan& p, const GxState& st,
                    const std::string& at) {
  EXPECT_EQ(st.texgen.num_texgens, static_cast<int>(p.texgens.size())) << at;
  for (const TexGenPlan& g : p.texgens) {
    const TexGen& s = st.texgen.texgens[static_cast<size_t>(g.coord.value())];
    EXPECT_EQ(s.type, g.type.value()) << at;
    EXPECT_EQ(s.source, g.source.value()) << at;
    EXPECT_EQ(s.matrix, g.matrix.value()) << at;
    if (g.matrix_values) {
      // GX_MTX2x4 loads two rows [OGC gx.c L2902-2918].
      const TexMatrix& mtx =
          st.texgen.matrices[static_cast<size_t>(g.matrix_values->slot.value() / 3)];
      for (size_t r = 0; r < 2; ++r)
        for (size_t c = 0; c < 4; ++c)
          EXPECT_EQ(mtx[r][c], g.matrix_values->values[r * 4 + c]) << at;
    }
    if (!g.texture) continue;
    const TexturePlan& t = *g.texture;
    const auto& loaded = st.textures[static_cast<size_t>(t.map.value())];
    ASSERT_TRUE(loaded.has_value()) << at << " " << t.object;
    EXPECT_EQ(loaded->width, t.width) << at;
    EXPECT_EQ(loaded->height, t.height) << at;
    EXPECT_EQ(loaded->format, t.format.value()) << at;
    EXPECT_EQ(loaded->wrap_s, t.wrap_s.value()) << at;
    EXPECT_EQ(loaded->wrap_t, t.wrap_t.value()) << at;
    EXPECT_EQ(loaded->data.size(), t.bytes) << at;
    const ArrayPlan* a = array_named(m, t.array);
    ASSERT_NE(a, nullptr) << at << " " << t.array;
    EXPECT_TRUE(std::equal(loaded->data.begin(), loaded->data.end(), a->bytes.begin())) << at;
  }
}

template <NameGroup In>
void expect_combiner(const CombinerPlan<In>& c, const TevCombiner& s, const std::string& at) {
  EXPECT_EQ(s.a, c.in[0].value()) << at;
  EXPECT_EQ(s.b, c.in[1].value()) << at;
  EXPECT_EQ(s.c, c.in[2].value()) << at;
  EXPECT_EQ(s.d, c.in[3].value()) << at;
  EXPECT_EQ(s.op, c.op.value()) << at;
  EXPECT_EQ(s.bias, c.bias.value()) << at;
  EXPECT_EQ(s.scale, c.scale.value()) << at;
  EXPECT_EQ(s.clamp, c.clamp.value() != 0) << at;
  EXPECT_EQ(s.dest, c.dest.value()) << at;
}

void expect_tev(const PassPlan& p, const GxState& st, const std::string& at) {
  EXPECT_EQ(st.tev.num_stages, static_cast<int>(p.stages.size())) << at;
  for (const TevStagePlan& s : p.stages) {
    const TevStage& t = st.tev.stages[static_cast<size_t>(s.stage.value())];
    const std::string where = at + " " + s.stage.name();
    EXPECT_EQ(t.texcoord, s.texcoord.value()) << where;
    EXPECT_EQ(t.texmap, s.texmap.value()) << where;
    EXPECT_EQ(t.channel, s.channel.value()) << where;
    expect_combiner(s.color, t.color, where + " colour");
    expect_combiner(s.alpha, t.alpha, where + " alpha");
    EXPECT_EQ(t.konst_alpha_sel, s.konst_alpha.value()) << where;
    // Unset: GX_Init's 1/4 (gx.md §1), which no stage the plan leaves unset reads as KONST.
    if (s.konst_color) EXPECT_EQ(t.konst_color_sel, s.konst_color->value()) << where;
  }
  if (p.konst_color) {
    const Color8& v = p.konst_color->value;
    EXPECT_EQ(st.tev.konst[static_cast<size_t>(p.konst_color->reg.value())], v) << at;
  }
  if (p.tev_register) {
    const Color8& v = p.tev_register->value;
    EXPECT_EQ(st.tev.registers[static_cast<size_t>(p.tev_register->reg.value())],
              (ColorS10{v.r, v.g, v.b, v.a}))
        << at;
  }
}

void expect_pixel_engine(const PixelEnginePlan& p, const GxState& st, const std::string& at) {
  EXPECT_EQ(st.blend.type, p.blend.value()) << at;
  EXPECT_EQ(st.blend.src, p.src.value()) << at;
  EXPECT_EQ(st.blend.dst, p.dst.value()) << at;
  EXPECT_EQ(st.blend.logic, p.logic.value()) << at;
  EXPECT_EQ(st.z.enable, p.z_enable.value() != 0) << at;
  EXPECT_EQ(st.z.func, p.z_func.value()) << at;
  EXPECT_EQ(st.z.update, p.z_update.value() != 0) << at;
  EXPECT_EQ(st.alpha_compare,
            (AlphaCompare{static_cast<u8>(p.alpha_comp0.value()), static_cast<u8>(p.alpha_ref0),
                          static_cast<u8>(p.alpha_op.value()),
                          static_cast<u8>(p.alpha_comp1.value()), static_cast<u8>(p.alpha_ref1)}))
      << at;
  EXPECT_EQ(st.cull_mode, p.cull.value()) << at;
  EXPECT_EQ(st.cull_mode, kCullNone) << at << ": every generated pass draws both sides";
}

const Function* function_named(const ProgramFile& f, const std::string& name) {
  for (const Function& fn : f.functions) {
    if (fn.name == name) return &fn;
  }
  return nullptr;
}

// Plans, emits, prints, parses and interprets; returns how many passes were compared.
int expect_plan_matches_program(const Scene& scene, const GxVariant& v, const std::string& at) {
  const ScenePlan plan = plan_scene(scene, v);
  const GeneratedPrograms g = emit_programs(plan);
  const ProgramFile back = parse_program(print_program(g.file), "printed.c");
  int passes = 0;
  for (const MaterialPlan& m : plan.materials) {
    for (size_t i = 0; i < m.passes.size(); ++i) {
      const std::string name = pass_function_name(m.c_name, static_cast<int>(i));
      const std::string where = at + " " + name;
      const Function* f = function_named(back, name);
      if (!f) {
        ADD_FAILURE() << where << ": no such function in the program";
        continue;
      }
      const GxState st = run_program(back.file, {&back.top_level, &f->body});
      const PassPlan& p = m.passes[i];
      expect_vertex_format(p.vertex, st, where);
      expect_lights(p, st, where);
      expect_channels(p, st, where);
      expect_texgens(m, p, st, where);
      expect_tev(p, st, where);
      expect_pixel_engine(p.pixel, st, where);
      ++passes;
    }
  }
  return passes;
}

TEST(GxPlan, EveryDemoSceneAndVariantProgramSetsWhatThePlanSays) {
  const char* const variants[] = {"t=vertex",
                                  "t=vertex:lut=16",
                                  "t=vertex:map=rgb565",
                                  "t=texgen",
                                  "t=texgen:view=object",
                                  "lobe=xf-spec",
                                  "lobe=xf-spec:view=object",
                                  "t=vertex:base=tev"};
  int compared = 0, xf_spec = 0, maps = 0;
  for (const char* folder : {"scenes", "scenes/ortho", "scenes/maps", "scenes/figures"}) {
    for (const std::string& s : test::json_files(folder)) {
      const Scene scene = load_scene(test::source_dir() / s);
      for (const char* text : variants) {
        const GxVariant v = parse_gx_variant(text);
        if (!refusal(scene, v).empty()) continue;
        const int n = expect_plan_matches_program(scene, v, s + " " + text);
        compared += n;
        xf_spec += v.lobe == GxVariant::Lobe::XfSpec ? n : 0;
        maps += s.find("map") != std::string::npos ? n : 0;
      }
    }
  }
  // Not vacuous: every kind of pass was planned and compared.
  std::printf("passes compared: %d (xf-spec %d, map scenes %d)\n", compared, xf_spec, maps);
  EXPECT_GT(compared, 100);
  EXPECT_GT(xf_spec, 0);
  EXPECT_GT(maps, 0);
}

// A plan that says something else than its program is caught: the comparison is not blind.
TEST(GxPlan, AChangedPlanNoLongerMatchesItsProgram) {
  const Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  ScenePlan plan = plan_scene(scene, GxVariant{});
  const GeneratedPrograms g = emit_programs(plan);
  const ProgramFile back = parse_program(print_program(g.file), "printed.c");
  const MaterialPlan& m = plan.materials.at(0);
  const Function* f = function_named(back, pass_function_name(m.c_name, 0));
  ASSERT_NE(f, nullptr);
  const GxState st = run_program(back.file, {&back.top_level, &f->body});
  PassPlan changed = m.passes.at(0);
  changed.stages.back().color.in[0] = {"GX_CC_TEXC"};
  EXPECT_NONFATAL_FAILURE(expect_tev(changed, st, "changed"), "changed GX_TEVSTAGE");
  changed = m.passes.at(0);
  changed.lights.back().color.g ^= 1;
  EXPECT_NONFATAL_FAILURE(expect_lights(changed, st, "changed"), "changed diffuse_light");
  changed = m.passes.at(0);
  changed.pixel.cull = {"GX_CULL_BACK"};
  EXPECT_NONFATAL_FAILURE(expect_pixel_engine(changed.pixel, st, "changed"), "changed");
}

// Issue 27: "Material.20" and "Material_20" are both Material_20 in C; the later one is
// suffixed, and reading the program back gives each material its own passes.
TEST(GxNames, CollidingMaterialNamesGetUniqueCNames) {
  Scene scene;
  for (const char* n : {"Material.20", "Material_20", "Material_20_2", "Material_20"}) {
    Material m;
    m.name = n;
    scene.materials.push_back(m);
  }
  EXPECT_EQ(material_c_names(scene),
            (std::vector<std::string>{"Material_20", "Material_20_2", "Material_20_2_2",
                                      "Material_20_3"}));
  EXPECT_EQ(pass_function_name("Material_20_2", 1), "ltrender_Material_20_2_pass1");
}

TEST(GxNames, CollidingMaterialsRenderExportAndReadBackToTheSameImage) {
  test::TempDir dir;
  test::write_file(dir / "quad.obj", test::quad_obj());
  test::write_file(dir / "two.json", R"({
    "image": { "width": 64, "height": 48 },
    "camera": { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 50 },
    "materials": {
      "Material.20": { "albedo": [0.9, 0.2, 0.1] },
      "Material_20": { "albedo": [0.1, 0.8, 0.3],
                       "translucency": { "power": 4, "distortion": 0.2, "ambient": 0.1 } } },
    "lights": [ { "type": "directional", "direction": [0, 0, -1], "intensity": 1 } ],
    "objects": [
      { "mesh": "quad.obj", "material": "Material.20", "transform": { "translate": [-1.1, 0, 0] } },
      { "mesh": "quad.obj", "material": "Material_20", "transform": { "translate": [1.1, 0, 0] } } ] })");
  const std::string scene = (dir / "two.json").string();
  const test::RunResult ex =
      test::run_ltrender("export gx " + scene + " -o " + (dir / "e.c").string());
  ASSERT_EQ(ex.exit_code, 0) << ex.err;
  const std::string c = test::read_file(dir / "e.c");
  EXPECT_NE(c.find("void ltrender_Material_20_pass0(void)"), std::string::npos);
  EXPECT_NE(c.find("void ltrender_Material_20_2_pass0(void)"), std::string::npos);
  EXPECT_NE(c.find("//   Material_20: \"Material.20\"\n"), std::string::npos) << c.substr(0, 3000);
  EXPECT_NE(c.find("//   Material_20_2: \"Material_20\"\n"), std::string::npos);
  const test::RunResult gen =
      test::run_ltrender("render " + scene + " --path gx -o " + (dir / "gen.png").string());
  ASSERT_EQ(gen.exit_code, 0) << gen.err;
  const test::RunResult back =
      test::run_ltrender("render " + scene + " --path gx --program " + (dir / "e.c").string() +
                         " -o " + (dir / "back.png").string());
  ASSERT_EQ(back.exit_code, 0) << back.err;
  EXPECT_EQ(test::read_file(dir / "gen.png"), test::read_file(dir / "back.png"));
  // Each quad shows its own material: the left one red, the right one green (the lookup maps
  // Material_20_2 back to "Material_20", not to "Material.20").
  const Scene s = load_scene(dir / "two.json");
  const ProgramFile file = load_program(dir / "e.c");
  const auto by_material = scene_programs(file, s);
  ASSERT_EQ(by_material.size(), 2u);
  EXPECT_EQ(by_material[0].at(0).name, "ltrender_Material_20_pass0");
  EXPECT_EQ(by_material[1].at(0).name, "ltrender_Material_20_2_pass0");
  EXPECT_EQ(by_material[0].at(0).state.lighting.material[0], (Color8{230, 51, 26, 255}));
  EXPECT_EQ(by_material[1].at(0).state.lighting.material[1], (Color8{26, 204, 77, 255}));
}

// A pass's t is one light's in the module's C (its figures) and in the emulator and the FIFO log
// (its number): sent_t_light holds them to one number. The planner's own passes agree (every
// module test); a plan whose second pass sends the first light's t is a bug, stopped.
TEST(GxPlanDeathTest, APassSendingAnotherLightsTIsABug) {
  const ScenePlan plan = plan_scene(load_scene(test::source_dir() / "scenes/three_point_blob.json"),
                                    parse_gx_variant("t=vertex"));
  const MaterialPlan& planned = plan.materials.front();
  ASSERT_GE(planned.passes.size(), 2u);
  ASSERT_TRUE(planned.passes[1].vertex.t);
  EXPECT_EQ(sent_t_light(planned, 1), 1u);
  MaterialPlan swapped = planned;
  swapped.passes[1].figures.light = 0;
  EXPECT_DEATH(sent_t_light(swapped, 1), "sends light 0's t");
}

}  // namespace
}  // namespace lt::gx
