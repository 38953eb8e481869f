#include "paths/gx/module/module_exporter.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <sstream>

#include "core/embedded.h"
#include "core/error.h"
#include "gx/program/pass_programs.h"
#include "gx/program/printer.h"
#include "paths/gx/generator.h"
#include "paths/gx/module/module_stored.h"
#include "paths/gx/module/module_textures.h"

namespace lt::gx {

namespace {

constexpr const char* kRuntimeDir = "src/paths/gx/module/runtime/";

std::string c_float(double v) {
  return print_arg(Arg::f32(static_cast<float>(v)));
}

template <typename V>
std::string c_vec3(const V& v, std::string (*print)(double)) {
  std::ostringstream o;
  o << "{" << print(v.x) << ", " << print(v.y) << ", " << print(v.z) << "}";
  return o.str();
}

Arg field(const std::string& expression) {
  return Arg::identifier(expression);
}

int slot_of(const LightObjectPlan& o) {
  return std::countr_zero(static_cast<unsigned>(o.slot.value()));
}

const LightObjectPlan& light_named(const PassPlan& p, const std::string& name) {
  for (const LightObjectPlan& o : p.lights) {
    if (o.name == name) return o;
  }
  LT_CHECK(false, "the pass has no light object " + name);
  return p.lights.front();
}

bool has_lut(const PassPlan& p) {
  for (const TexGenPlan& g : p.texgens) {
    if (g.texture && g.texture->role == TexturePlan::Role::Lut) return true;
  }
  return false;
}

// "Stage 1: trans = w x COLOR0 x 2" -> "Stage 1: trans = w x COLOR0 x s->translucency_scale
// (chosen per frame)".
std::string runtime_scale_comment(const std::string& what, const std::string& scale) {
  const auto at = what.rfind(" x ");
  const std::string head = at == std::string::npos ? what : what.substr(0, at);
  return head + " x s->" + scale + " (chosen per frame)";
}

// Which per-frame scale a stage takes, as the plan says (TevStagePlan::frame_scale): the
// translucency's, the diffuse's, or none (empty).
std::string stage_scale(const PassPlan& p, size_t stage) {
  switch (p.stages[stage].frame_scale) {
    case TevStagePlan::FrameScale::Translucency:
      return "translucency_scale";
    case TevStagePlan::FrameScale::Diffuse:
      return "diffuse_scale";
    case TevStagePlan::FrameScale::None:
      break;
  }
  return "";
}

// The pass function as the plan emitted it, with every per-frame number read from the state
// `s` that ltr_pass_setup fills: light positions, colours and distance coefficients, the
// ambient registers, REG0, the TEV scales and (t from the normal) the texture matrix.
Function bind_frame_state(Function f, const PassPlan& p, bool t_from_normal) {
  f.parameters = "ltr_pass_state* s";
  const auto cut = f.comment.find(", scales:");
  if (cut != std::string::npos) f.comment = f.comment.substr(0, cut);
  f.comment +=
      "\nThe light objects, ambient colours, REG0 and TEV scales are this frame's (s, filled by "
      "ltr_pass_setup).";
  std::vector<Statement> body;
  std::string carried_comment;
  for (Statement st : f.body) {
    if (st.kind == Statement::Kind::Declaration) {
      if (t_from_normal && st.declaration.type == Declaration::Type::Mtx) {
        carried_comment = st.comment + " (this frame's V and L)";
        continue;
      }
      body.push_back(std::move(st));
      continue;
    }
    Call& c = st.call;
    const std::string& fn = c.function;
    auto slot = [&] {
      return "s->light[" + std::to_string(slot_of(light_named(p, c.args[0].name))) + "]";
    };
    if (fn == "GX_InitLightPos") {
      const std::string l = slot();
      for (size_t i = 0; i < 3; ++i)
        c.args[i + 1] = field(l + ".position[" + std::to_string(i) + "]");
    } else if (fn == "GX_InitLightColor") {
      c.args[1] = field("LTR_GXCOLOR(" + slot() + ".color)");
    } else if (fn == "GX_InitLightDir" &&
               light_named(p, c.args[0].name).kind == LightObjectPlan::Kind::SpecularFit) {
      const std::string l = slot();
      for (size_t i = 0; i < 3; ++i)
        c.args[i + 1] = field(l + ".direction[" + std::to_string(i) + "]");
      st.comment =
          "-u: the slot holds this frame's u = +-d V, eye space (x = N.u >= 0 on front faces)";
    } else if (fn == "GX_InitLightAttn") {
      const std::string l = slot();
      for (size_t i = 0; i < 3; ++i) {
        c.args[i + 1] = field(l + ".a[" + std::to_string(i) + "]");
        c.args[i + 4] = field(l + ".k[" + std::to_string(i) + "]");
      }
      st.comment =
          "A(x) = (a0 + a1 x + a2 x^2) / (k0 + k1 x + k2 x^2), fitted to this frame's lobe "
          "(ltr_fit_lobe)";
    } else if (fn == "GX_InitLightAttnK") {
      const std::string l = slot();
      for (size_t i = 0; i < 3; ++i) c.args[i + 1] = field(l + ".k[" + std::to_string(i) + "]");
      st.comment = "k = (kc, kl, kq) / gain: the XF computes gain x att, the light's magnitude";
    } else if (fn == "GX_SetChanAmbColor") {
      const int ch = c.args[0].value == GxConst<NameGroup::Channel>{"GX_COLOR1A1"}.value() ? 1 : 0;
      c.args[1] = field("LTR_GXCOLOR(s->ambient[" + std::to_string(ch) + "])");
    } else if (fn == "GX_SetTevColor") {
      c.args[1] = field("LTR_GXCOLOR(s->reg0)");
    } else if (fn == "GX_SetTevColorOp") {
      const std::string scale = stage_scale(p, static_cast<size_t>(c.args[0].value));
      if (!scale.empty()) c.args[3] = field("LTR_TEV_SCALE(s->" + scale + ")");
    } else if (fn == "GX_SetTevOrder") {
      const size_t stage = static_cast<size_t>(c.args[0].value);
      const std::string scale = stage_scale(p, stage);
      if (!scale.empty()) st.comment = runtime_scale_comment(p.stages[stage].what, scale);
    } else if (fn == "GX_LoadTexMtxImm" && t_from_normal) {
      c.args[0] = field("s->lut_matrix");
      st.comment = carried_comment;
    }
    body.push_back(std::move(st));
  }
  f.body = std::move(body);
  return f;
}

std::string light_kinds(const Scene& scene, const GxVariant& variant) {
  std::ostringstream o;
  const size_t n = scene.lights.size();
  o << "#define LTRENDER_LIGHTS " << n << "\n"
    << "// Each light's type and distance attenuation, fixed at export (a directional light: 1, 0, "
       "0).\n"
    << "const ltr_light_kind ltrender_light_kinds[" << std::max<size_t>(n, 1) << "] = {";
  if (n == 0) o << "{0, 1.0, 0.0, 0.0}";  // C has no empty array; no pass reads it
  for (size_t l = 0; l < n; ++l) {
    const Light& L = scene.lights[l];
    o << (l ? ", " : "") << "{" << (L.type == Light::Type::Point) << ", " << c_double(L.kc) << ", "
      << c_double(L.kl) << ", " << c_double(L.kq) << "}";
  }
  o << "};\n"
    << "const ltr_scene ltrender_scene = {ltrender_light_kinds, LTRENDER_LIGHTS, "
    << c_vec3(scene.ambient_light, c_double) << "};\n\n";
  if (variant.light_range)
    o << "// --light-range: no point light comes closer than this to a vertex it lights (world "
         "units);\n// the TEV scales are chosen for the attenuation there "
         "(ltr_declared_range). A light that\n// comes closer saturates where it is brighter.\n"
      << "#define LTRENDER_LIGHT_RANGE " << c_double(*variant.light_range) << "\n\n";
  const Camera& cam = scene.camera;
  o << "// The scene's camera and lights as exported: where a game starts from (world space).\n"
    << "#define LTRENDER_ORTHOGRAPHIC " << (cam.projection == Camera::Projection::Orthographic)
    << "\n"
    << "#define LTRENDER_FOV_Y_DEG " << c_float(cam.fov_y_deg) << "\n"
    << "#define LTRENDER_ORTHO_HEIGHT " << c_float(cam.height) << "\n"
    << "#define LTRENDER_NEAR " << c_float(cam.near) << "\n"
    << "#define LTRENDER_FAR " << c_float(cam.far) << "\n"
    << "const ltr_camera ltrender_scene_camera = {" << c_vec3(cam.eye, c_float) << ", "
    << c_vec3(cam.target, c_float) << ", " << c_vec3(cam.up, c_float) << "};\n"
    << "const ltr_light ltrender_scene_lights[" << std::max<size_t>(n, 1) << "] = {";
  if (n == 0) o << "{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, 0.0f}";
  for (size_t l = 0; l < n; ++l) {
    const Light& L = scene.lights[l];
    o << (l ? ",\n    " : "") << "{" << c_vec3(L.position, c_float) << ", "
      << c_vec3(L.direction, c_float) << ", " << c_vec3(L.color, c_float) << ", "
      << c_float(L.translucency_scale) << "}";
  }
  o << "};\n\n"
    << "// The view of a camera, in the projection the scene was exported with.\n"
    << "void ltrender_view(const ltr_camera* camera, ltr_view* view) {\n"
    << "  ltr_view_of(camera, LTRENDER_ORTHOGRAPHIC, view);\n"
    << "}\n";
  return o.str();
}

// The material's fixed constants, the shape of its passes, and its setup, t and draw functions.
// A stored module (module_stored.h) draws with ltrender_draw_stored: no per-mesh draw.
std::string material_functions(const Scene& scene, const MaterialPlan& m, const GxVariant& v,
                               bool stored) {
  const Material& mat = scene.materials[static_cast<size_t>(m.material)];
  const std::string id = "ltrender_" + m.c_name;
  const std::string passes = "LTRENDER_" + m.c_name + "_PASSES";
  glm::dvec3 tint(1);
  double a = 0, d = 0, t_max = 1, power = 0;
  bool normalize_h = false;
  if (mat.translucency) {
    const Translucency& tr = *mat.translucency;
    if (tr.thickness_source != ThicknessSource::Constant) tint = tr.tint;
    a = tr.ambient;
    d = tr.distortion;
    normalize_h = tr.normalize_distorted_light;
    power = tr.power;
  }
  bool sends_t = false;
  for (const PassPlan& p : m.passes) {
    if (!p.figures.diffuse_only) t_max = p.figures.thickness_scale;
    sends_t = sends_t || p.vertex.t;
  }
  const bool t_from_normal = v.t == GxVariant::TexCoord::Texgen;
  std::ostringstream o;
  o << "\n// Material " << mat.name << ": what the export fixed.\n"
    << "#define " << passes << " " << m.passes.size() << "\n"
    << "const ltr_material " << id << "_material = {" << c_vec3(mat.albedo, c_double) << ", "
    << c_vec3(tint, c_double) << ", " << c_double(a) << ", " << c_double(d) << ", " << normalize_h
    << ", " << c_double(t_max) << ", " << v.lut_size << ", " << t_from_normal << ", "
    << v.view_object << ", " << (v.lobe == GxVariant::Lobe::XfSpec) << ", " << c_double(power)
    << "};\n"
    << "// Per pass: diffuse only, first light, lights, translucent, LUT.\n"
    << "const ltr_pass_shape " << id << "_shapes[" << passes << "] = {";
  for (size_t i = 0; i < m.passes.size(); ++i) {
    const PassPlan& p = m.passes[i];
    const bool translucent = !p.figures.diffuse_only && p.channels.front().enable.value() != 0;
    o << (i ? ", " : "") << "{" << p.figures.diffuse_only << ", " << p.figures.light << ", "
      << (p.figures.diffuse_only ? p.lights.size() : 1) << ", " << translucent << ", " << has_lut(p)
      << "}";
  }
  o << "};\n\n"
    << "// Every frame, before drawing " << mat.name << ": the state of each pass from the view,\n"
    << "// the lights (world space) and the material's meshes as drawn this frame (world space).\n"
    << (v.light_range
            ? "// The TEV scales come from the declared light range (LTRENDER_LIGHT_RANGE: no "
              "point "
              "light\n// comes closer to a vertex), not from the meshes' vertices.\n"
            : "// The TEV scales come from what the lights do at the vertices that can be seen, so "
              "every\n// mesh of the material takes part (ltr_light_range_of: its cost per vertex "
              "and light).\n")
    << (v.view_object
            ? "// :view=object: V and L are taken at the centre of these meshes (ltr_centre_of), "
              "so "
              "the\n// texture matrix of t is this frame's; set up one mesh at a time for a V per "
              "mesh.\n"
            : "")
    << (v.lobe == GxVariant::Lobe::XfSpec
            ? "// lobe=xf-spec: the lobe is fitted again for this frame's V.L (ltr_fit_lobe: its "
              "cost\n// per translucent light, and what a game may keep between frames).\n"
            : "")
    << "void " << id
    << "_setup(const ltr_view* view, const ltr_light lights[], const ltr_mesh meshes[],\n"
    << "    int mesh_count, ltr_pass_state state[" << passes << "]) {\n"
    << "  ltr_light_range ranges[LTRENDER_LIGHTS + 1];\n"
    << "  double centre[3] = {0, 0, 0};\n"
    << "  int l, " << (v.light_range ? "" : "m, ") << "p;\n";
  if (v.view_object)
    o << "  ltr_centre_of(meshes, mesh_count, centre);\n";
  else if (v.light_range)
    o << "  (void)meshes;\n  (void)mesh_count;\n";
  if (v.light_range) {
    o << "  for (l = 0; l < LTRENDER_LIGHTS; ++l)\n"
      << "    ltr_declared_range(&ltrender_light_kinds[l], LTRENDER_LIGHT_RANGE, &ranges[l]);\n";
  } else {
    o << "  for (l = 0; l < LTRENDER_LIGHTS; ++l) {\n"
      << "    ranges[l].max_attenuation = ranges[l].max_diffuse = 0;\n"
      << "    for (m = 0; m < mesh_count; ++m)\n"
      << "      ltr_light_range_of(view, &ltrender_light_kinds[l], &lights[l], &meshes[m], "
         "&ranges[l]);\n"
      << "  }\n";
  }
  o << "  for (p = 0; p < " << passes << "; ++p)\n"
    << "    ltr_pass_setup(&ltrender_scene, &" << id << "_material, &" << id
    << "_shapes[p], view, lights, ranges, centre, &state[p]);\n"
    << "}\n";
  if (sends_t) {
    o << "\n// The t of light `light` at every vertex of `mesh` (ltr_fill_t: V, L and the cost).\n"
      << "void " << id << "_fill_t(const ltr_view* view, const ltr_light lights[], int light,\n"
      << "    const ltr_mesh* mesh, float* t) {\n"
      << "  ltr_fill_t(view, &ltrender_light_kinds[light], &lights[light], &" << id
      << "_material, mesh, t);\n"
      << "}\n";
  }
  if (stored) return o.str();
  o << "\n// Draws one mesh of " << mat.name << " through every pass (after " << id
    << "_setup and\n"
    << "// ltr_load_view). t_scratch holds mesh->vertex_count floats"
    << (sends_t ? " (each pass's t)" : " (unused: no pass sends t)") << ".\n"
    << "void " << id << "_draw(ltr_pass_state state[" << passes << "], const ltr_view* view,\n"
    << "    const ltr_light lights[], const ltr_mesh* mesh, float* t_scratch) {\n"
    << "  (void)view;\n  (void)lights;\n  (void)t_scratch;\n";
  for (size_t i = 0; i < m.passes.size(); ++i) {
    const PassPlan& p = m.passes[i];
    o << "  " << pass_function_name(m.c_name, static_cast<int>(i)) << "(&state[" << i << "]);\n";
    if (p.vertex.t)
      o << "  " << id << "_fill_t(view, lights, " << sent_t_light(m, i) << ", mesh, t_scratch);\n";
    o << "  ltr_draw_mesh(mesh, " << p.vertex.colour << ", " << (p.vertex.t ? "t_scratch" : "0")
      << ", " << p.vertex.uv << ");\n";
  }
  o << "}\n";
  return o.str();
}

std::string without_line(std::string text, const std::string& line) {
  const auto at = text.find(line);
  if (at != std::string::npos) text.erase(at, line.size());
  return text;
}

// The runtime the module embeds: the maths header and source (plain C99) and the libogc draw.
std::string module_runtime_source(const std::string& file) {
  const auto& table = embedded::sources();
  const auto it = table.find(kRuntimeDir + file);
  LT_CHECK(it != table.end(), "no embedded module runtime " + file);
  return it->second;
}

}  // namespace

std::string export_module(const Scene& scene, const GxVariant& variant,
                          const std::string& scene_argument) {
  if (variant.base_in_tev)
    throw InputError("--variant", to_string(variant),
                     "gx: --format module does not carry base=tev: its setup recomputes the XF "
                     "light and a grey REG0 each frame, not the konst colour; use base=xf");
  const ScenePlan plan = plan_scene(scene, variant);
  // The F32 mesh goes in directly, every frame (ltrender_gx_draw.c); a stored one as the game
  // ships it, indexed (module_stored.h, ltrender_gx_stored.c).
  const bool stored = !variant.storage.is_default() || variant.draw != GxVariant::Draw::Direct;
  if (stored) {
    const std::string why = stored_module_refusal(variant);
    if (!why.empty()) throw InputError("--variant", to_string(variant), "gx: " + why);
  }
  const GeneratedPrograms g = emit_programs(plan);
  const bool t_from_normal = variant.t == GxVariant::TexCoord::Texgen;
  std::ostringstream out;
  out << "// Generated by `ltrender export gx " << scene_argument << " --variant "
      << to_string(variant) << " --format module`.\n"
      << "// The translucency term for the Wii's GX as a module a game runs every frame: the same "
         "plan\n"
      << "// as `--format c`, with everything that depends on the camera and the lights computed "
         "here\n"
      << "// from the game's own (world space):\n"
      << "//   ltr_camera camera = ...; ltr_light lights[LTRENDER_LIGHTS] = ...;  // this frame's\n"
      << "//   ltr_view view; ltrender_view(&camera, &view); ltr_load_view(&view);\n"
      << "//   per material: ltrender_<material>_setup(&view, lights, meshes, n, state);\n"
      << "//                 per mesh: ltrender_<material>_draw(state, &view, lights, &mesh, t);\n"
      << "// Setup puts the lights in eye space (a directional light far along its direction, as\n"
      << "// libogc's GX_InitSpecularDir does), divides each light's magnitude into its distance\n"
      << "// coefficients, and chooses the TEV scales from the lights' range over the visible "
         "vertices\n// (or, with --light-range, from the declared bound).\n"
      << "// Fixed at export: the materials, the light types and attenuations, the ambient light, "
         "which\n"
      << "// lights add translucency (a light whose colour or scale becomes 0 keeps its stages).\n"
      << "// Compile with -ffp-contract=off to get ltrender's numbers to the bit "
         "(ltrender_gx_runtime.h).\n"
      << "// Cost per frame: ltr_light_range_of per light and vertex of every mesh; per pass that\n"
      << "// sends t, ltr_fill_t per vertex (both state their flops). One module per program: the "
         "ltr_\n"
      << "// runtime functions are not static.\n"
      << (stored
              ? "// Stored variant: the meshes are the module's own, converted once (object "
                "space,\n// quantised, indexed); call ltrender_stored_init() once after GX_Init, "
                "and each frame,\n// after the setups, ltrender_draw_stored(&view, lights, "
                "objects, states) "
                "instead of the\n// _draw functions (objects[o]: scene object o's world-space "
                "mesh, where a pass's t comes from).\n" +
                    stored_cost_comment(scene, variant)
              : std::string())
      << "\n#include <gccore.h>\n#include <math.h>\n\n"
      << (variant.vat != 0 ? "// :vat=" + std::to_string(variant.vat) +
                                 ": the passes declare and the draws name this vertex format.\n"
                                 "#define LTRENDER_VTXFMT GX_VTXFMT" +
                                 std::to_string(variant.vat) + "\n\n"
                           : std::string())
      << "// ---- runtime: the per-frame maths (plain C99) ----\n"
      << module_runtime_source("ltrender_gx_runtime.h") << "\n"
      << without_line(module_runtime_source("ltrender_gx_runtime.c"),
                      "#include \"ltrender_gx_runtime.h\"\n")
      << "\n// ---- runtime: the view matrix and the draw (libogc) ----\n"
      << module_runtime_source("ltrender_gx_draw.c") << "\n"
      << (stored ? "// ---- runtime: the stored meshes' draw (libogc) ----\n" +
                       module_runtime_source("ltrender_gx_stored.c") + "\n"
                 : std::string())
      << "// ---- the scene ----\n"
      << light_kinds(scene, variant);
  ProgramFile file = g.file;
  file.comment.clear();
  const ModuleTextures textures = module_textures(plan);
  file.top_level = with_textures_in_tpl(file.top_level, textures);
  std::vector<Function> bound;
  for (const MaterialPlan& m : plan.materials) {
    for (size_t i = 0; i < m.passes.size(); ++i) {
      const std::string name = pass_function_name(m.c_name, static_cast<int>(i));
      const auto f = std::find_if(file.functions.begin(), file.functions.end(),
                                  [&](const Function& fn) { return fn.name == name; });
      LT_CHECK(f != file.functions.end(), "emit_programs wrote no " + name);
      bound.push_back(
          take_textures_from_tpl(bind_frame_state(*f, m.passes[i], t_from_normal), textures));
    }
  }
  file.functions = std::move(bound);
  out << "\n// ---- the passes ----\n" << print_program(file);
  for (const MaterialPlan& m : plan.materials) out << material_functions(scene, m, variant, stored);
  if (stored) out << stored_meshes_c(scene, plan, variant);
  out << open_textures_function(textures) << "\n// ---- every material ----\n"
      << "typedef struct {\n"
      << "  const char* name; /* as the scene names it */\n"
      << "  int passes;\n"
      << "  void (*setup)(const ltr_view*, const ltr_light[], const ltr_mesh[], int, "
         "ltr_pass_state[]);\n"
      << "  void (*draw)(ltr_pass_state[], const ltr_view*, const ltr_light[], const ltr_mesh*, "
         "float*);\n"
      << (stored ? "  /* draw is 0: a stored module draws with ltrender_draw_stored */\n" : "")
      << "} ltr_material_module;\n"
      << "#define LTRENDER_MATERIALS " << plan.materials.size() << "\n"
      << "#define LTRENDER_MAX_PASSES ";
  size_t most = 1;
  for (const MaterialPlan& m : plan.materials) most = std::max(most, m.passes.size());
  out << most << "\n"
      << "const ltr_material_module ltrender_materials["
      << std::max<size_t>(plan.materials.size(), 1) << "] = {";
  if (plan.materials.empty()) out << "{\"\", 0, 0, 0}";
  for (size_t i = 0; i < plan.materials.size(); ++i) {
    const MaterialPlan& m = plan.materials[i];
    std::string quoted;
    for (char c : m.name)
      quoted += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    out << (i ? ",\n    " : "\n    ") << "{\"" << quoted << "\", LTRENDER_" << m.c_name
        << "_PASSES, ltrender_" << m.c_name << "_setup, "
        << (stored ? std::string("0") : "ltrender_" + m.c_name + "_draw") << "}";
  }
  out << "};\n";
  return out.str();
}

}  // namespace lt::gx
