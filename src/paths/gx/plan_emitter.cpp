// emit_programs: the plan as libogc calls, in the order a porter reads a pass (vertex format,
// lights, channels, texgens and textures, TEV, pixel engine). It chooses nothing: every value
// comes from the plan, every constant is a GxConst checked at compile time.
#include "gx/program/pass_programs.h"
#include "paths/gx/generator.h"

namespace lt::gx {

namespace {

using NG = NameGroup;

template <NameGroup Group>
Arg gx(GxConst<Group> c) {
  return Arg::integer(c.name(), c.value());
}
Arg num(float v) {
  return Arg::f32(v);
}
Arg lit(long long v) {
  return Arg::literal(v);
}
Arg rgb(const Color8& c) {
  return Arg::rgba({c.r, c.g, c.b, c.a});
}

// One program being written: statements in order, with comments for the porter.
class Writer {
 public:
  void call(const std::string& f, std::vector<Arg> args, const std::string& comment = "") {
    body.push_back(Statement::of(Call(f, std::move(args)), comment));
  }
  void declare(Declaration::Type t, const std::string& name, std::vector<double> values = {},
               const std::string& comment = "") {
    Declaration d;
    d.type = t;
    d.name = name;
    d.values = std::move(values);
    body.push_back(Statement::of(std::move(d), comment));
  }
  std::vector<Statement> body;
};

// GX_SetVtxAttrFmt's type argument: a component type (GX_S16) or, for GX_VA_CLR0, a colour
// encoding (GX_RGB565); one field, two groups of libogc names [OGC gx.h L93-103].
Arg component_type(ComponentType t) {
  return Arg::integer(component_type_name(t), static_cast<long long>(t));
}
Arg color_type(ColorType t) {
  return Arg::integer(color_type_name(t), static_cast<long long>(t));
}

void vertex_format(Writer& w, const VertexFormatPlan& v) {
  const VertexDeclarations& d = v.declared;
  const auto fmt = GxConst<NG::VtxFmt>::with_value(d.format);
  w.call("GX_ClearVtxDesc", {},
         v.uv ? "Vertex format: position and normal (and t) as sent, and the mesh's UV for the "
                "thickness map"
              : "Vertex format: position and normal (and the baked thickness colour / t) as sent");
  // An NBT is declared as libogc takes it: GX_VA_NBT in the descriptor and the format, with
  // GX_NRM_NBT or GX_NRM_NBT3 [OGC gx.c __SETVCDATTR, __SETVCDFMT L2549-2554].
  const NormalVectors vectors = d.storage.normal_vectors;
  const GxConst<NG::VtxAttr> pos{"GX_VA_POS"}, clr0{"GX_VA_CLR0"}, tex0{"GX_VA_TEX0"},
      nrm = vectors == NormalVectors::Normal ? GxConst<NG::VtxAttr>{"GX_VA_NRM"}
                                             : GxConst<NG::VtxAttr>{"GX_VA_NBT"};
  const auto uv_va = GxConst<NG::VtxAttr>::with_value(tex0.value() + v.uv_attribute());
  // Each attribute GX_DIRECT, or under an indexed :draw= the index its array takes (the GX_VA_*
  // values are the array numbers plus GX_VA_POS [OGC gx.h L82-92]).
  auto input = [&](GxConst<NG::VtxAttr> a) {
    if (!d.indexed) return gx(GxConst<NG::VtxAttrType>{"GX_DIRECT"});
    const auto array =
        a.value() == nrm.value() ? kArrayNormal : static_cast<int>(a.value() - pos.value());
    const bool wide = d.index16[static_cast<size_t>(array)];
    return wide ? gx(GxConst<NG::VtxAttrType>{"GX_INDEX16"})
                : gx(GxConst<NG::VtxAttrType>{"GX_INDEX8"});
  };
  w.call("GX_SetVtxDesc", {gx(pos), input(pos)},
         d.indexed ? "Indexed: GX_SetArray(attribute, array, stride) of each before the draw" : "");
  w.call("GX_SetVtxDesc", {gx(nrm), input(nrm)});
  if (v.colour) w.call("GX_SetVtxDesc", {gx(clr0), input(clr0)});
  if (v.t) w.call("GX_SetVtxDesc", {gx(tex0), input(tex0)});
  if (v.uv) w.call("GX_SetVtxDesc", {gx(uv_va), input(uv_va)});
  auto format = [&](GxConst<NG::VtxAttr> a, GxConst<NG::CompCount> n, Arg type, int frac) {
    w.call("GX_SetVtxAttrFmt", {gx(fmt), gx(a), gx(n), std::move(type), lit(frac)});
  };
  const VertexStorage& s = d.storage;
  // A position's and texture coordinate's fraction as stored; F32 takes none. A normal's exponent
  // is its type's, and libogc writes no fraction for it [OGC gx.c __SETVCDFMT L2545-2555].
  auto fraction = [](const CoordinateStorage& c) {
    return c.type == ComponentType::F32 ? 0 : c.frac;
  };
  format(pos, {"GX_POS_XYZ"}, component_type(s.position.type), fraction(s.position));
  format(nrm,
         vectors == NormalVectors::Normal ? GxConst<NG::CompCount>{"GX_NRM_XYZ"}
         : vectors == NormalVectors::Nbt  ? GxConst<NG::CompCount>{"GX_NRM_NBT"}
                                          : GxConst<NG::CompCount>{"GX_NRM_NBT3"},
         component_type(s.normal), 0);
  // GX_CLR_RGB for an encoding without alpha, as a port writes it; the loader reads the
  // encoding alone (vertex_format.h ColorFormat).
  const bool alpha =
      s.color == ColorType::Rgba4 || s.color == ColorType::Rgba6 || s.color == ColorType::Rgba8;
  if (v.colour)
    format(clr0,
           alpha ? GxConst<NG::CompCount>{"GX_CLR_RGBA"} : GxConst<NG::CompCount>{"GX_CLR_RGB"},
           color_type(s.color), 0);
  if (v.t) format(tex0, {"GX_TEX_S"}, component_type(s.texcoord.type), fraction(s.texcoord));
  if (v.uv) format(uv_va, {"GX_TEX_ST"}, component_type(s.texcoord.type), fraction(s.texcoord));
}

void light_object(Writer& w, const LightObjectPlan& o) {
  const Arg self = Arg::address_of(o.name);
  w.declare(Declaration::Type::LightObj, o.name);
  w.call("GX_InitLightPos", {self, num(o.position.x), num(o.position.y), num(o.position.z)});
  w.call("GX_InitLightColor", {self, rgb(o.color)});
  w.call("GX_InitLightDir",
         {self, num(o.direction_arg.x), num(o.direction_arg.y), num(o.direction_arg.z)});
  if (o.kind == LightObjectPlan::Kind::Distance) {
    w.call("GX_InitLightSpot", {self, num(90), gx(GxConst<NG::SpotFn>{"GX_SP_OFF"})});
    const std::string g = note_number(o.gain);
    w.call("GX_InitLightAttnK", {self, num(o.k[0]), num(o.k[1]), num(o.k[2])},
           "k = (kc, kl, kq) / " + g + ": XF attenuation = " + g + " x att, the light's magnitude");
  } else {
    w.call("GX_InitLightAttn",
           {self, num(o.a[0]), num(o.a[1]), num(o.a[2]), num(o.k[0]), num(o.k[1]), num(o.k[2])},
           "A(x) = (a0 + a1 x + a2 x^2) / (k0 + k1 x + k2 x^2), fitted to the lobe");
  }
  w.call("GX_LoadLightObj", {self, gx(o.slot)});
}

Arg light_mask(const LightMask& m) {
  if (m.bits == 0) return gx(GxConst<NG::Light>{"GX_LIGHTNULL"});
  if (m.named) return gx(GxConst<NG::Light>::with_value(m.bits));
  return lit(m.bits);
}

void channels(Writer& w, const PassPlan& p) {
  w.call("GX_SetNumChans", {lit(static_cast<long long>(p.channels.size()))}, p.channels_what);
  for (const ChannelPlan& c : p.channels) {
    w.call("GX_SetChanCtrl",
           {gx(c.channel), gx(c.enable), gx(c.ambient_source), gx(c.material_source),
            light_mask(c.lights), gx(c.diffuse_fn), gx(c.attenuation_fn)},
           c.what);
    if (c.ambient) w.call("GX_SetChanAmbColor", {gx(c.channel), rgb(*c.ambient)});
    if (c.material)
      w.call("GX_SetChanMatColor", {gx(c.channel), rgb(*c.material)}, c.material_what);
  }
}

void texture(Writer& w, const TexturePlan& t) {
  const Arg self = Arg::address_of(t.object);
  const GxConst<NG::Bool> mipmap =
      t.mip ? GxConst<NG::Bool>{"GX_TRUE"} : GxConst<NG::Bool>{"GX_FALSE"};
  w.declare(Declaration::Type::TexObj, t.object);
  if (t.tlut) {
    const Arg tlut = Arg::address_of(t.tlut->object);
    w.declare(Declaration::Type::TlutObj, t.tlut->object);
    w.call("GX_InitTlutObj",
           {tlut, Arg::identifier(t.tlut->array), gx(t.tlut->format), lit(t.tlut->entries)});
    w.call("GX_LoadTlut", {tlut, gx(t.tlut->name)});
    w.call("GX_InitTexObjCI",
           {self, Arg::identifier(t.array), lit(t.width), lit(t.height), gx(t.format), gx(t.wrap_s),
            gx(t.wrap_t), gx(mipmap), gx(t.tlut->name)},
           t.what);
  } else {
    w.call("GX_InitTexObj",
           {self, Arg::identifier(t.array), lit(t.width), lit(t.height), gx(t.format), gx(t.wrap_s),
            gx(t.wrap_t), gx(mipmap)},
           t.what);
  }
  if (t.mip)
    w.call("GX_InitTexObjLOD",
           {self, gx(t.mip->min_filter), gx(GxConst<NG::TexFilter>{"GX_LINEAR"}), Arg::f32(0.0f),
            Arg::f32(t.mip->max_lod), Arg::f32(t.mip->bias), gx(GxConst<NG::Bool>{"GX_FALSE"}),
            gx(t.mip->edge_lod ? GxConst<NG::Bool>{"GX_TRUE"} : GxConst<NG::Bool>{"GX_FALSE"}),
            gx(GxConst<NG::Anisotropy>{"GX_ANISO_1"})},
           t.mip->edge_lod ? "LOD range 0 .. the last level, edge LOD"
                           : "LOD range 0 .. the last level, diagonal LOD");
  w.call("GX_LoadTexObj", {self, gx(t.map)});
}

// The matrices first (GX_LoadTexMtxImm), then the count, then each texgen with the texture its
// coordinates fetch.
void texgens(Writer& w, const PassPlan& p) {
  for (const TexGenPlan& g : p.texgens) {
    if (!g.matrix_values) continue;
    const TexMatrixPlan& m = *g.matrix_values;
    w.declare(Declaration::Type::Mtx, m.name, std::vector<double>(m.values.begin(), m.values.end()),
              m.what);
    w.call("GX_LoadTexMtxImm",
           {Arg::identifier(m.name), gx(m.slot), gx(GxConst<NG::MtxType>{"GX_MTX2x4"})});
  }
  w.call("GX_SetNumTexGens", {lit(static_cast<long long>(p.texgens.size()))});
  for (const TexGenPlan& g : p.texgens) {
    w.call("GX_SetTexCoordGen", {gx(g.coord), gx(g.type), gx(g.source), gx(g.matrix)}, g.what);
    if (g.texture) texture(w, *g.texture);
  }
}

template <NameGroup In>
std::vector<Arg> combiner_in(const Arg& stage, const CombinerPlan<In>& c) {
  return {stage, gx(c.in[0]), gx(c.in[1]), gx(c.in[2]), gx(c.in[3])};
}
template <NameGroup In>
std::vector<Arg> combiner_op_args(const Arg& stage, const CombinerPlan<In>& c) {
  return {stage, gx(c.op), gx(c.bias), gx(c.scale), gx(c.clamp), gx(c.dest)};
}

void tev(Writer& w, const PassPlan& p) {
  w.call("GX_SetNumTevStages", {lit(static_cast<long long>(p.stages.size()))});
  if (p.tev_register)
    w.call("GX_SetTevColor", {gx(p.tev_register->reg), rgb(p.tev_register->value)},
           p.tev_register->what);
  if (p.konst_color)
    w.call("GX_SetTevKColor", {gx(p.konst_color->reg), rgb(p.konst_color->value)},
           p.konst_color->what);
  for (const TevStagePlan& s : p.stages) {
    const Arg stage = gx(s.stage);
    w.call("GX_SetTevOrder", {stage, gx(s.texcoord), gx(s.texmap), gx(s.channel)}, s.what);
    if (s.konst_color) w.call("GX_SetTevKColorSel", {stage, gx(*s.konst_color)});
    w.call("GX_SetTevColorIn", combiner_in(stage, s.color));
    w.call("GX_SetTevColorOp", combiner_op_args(stage, s.color));
    w.call("GX_SetTevAlphaIn", combiner_in(stage, s.alpha));
    w.call("GX_SetTevKAlphaSel", {stage, gx(s.konst_alpha)});
    w.call("GX_SetTevAlphaOp", combiner_op_args(stage, s.alpha));
  }
}

void pixel_engine(Writer& w, const PixelEnginePlan& p) {
  w.call("GX_SetBlendMode", {gx(p.blend), gx(p.src), gx(p.dst), gx(p.logic)}, p.what);
  w.call("GX_SetZMode", {gx(p.z_enable), gx(p.z_func), gx(p.z_update)});
  w.call("GX_SetAlphaCompare", {gx(p.alpha_comp0), lit(p.alpha_ref0), gx(p.alpha_op),
                                gx(p.alpha_comp1), lit(p.alpha_ref1)});
  w.call("GX_SetCullMode", {gx(p.cull)},
         "Draw both sides (GX_Init's GX_CULL_BACK would cull the faces wound counter-clockwise)");
}

std::vector<Statement> pass_body(const PassPlan& p) {
  Writer w;
  vertex_format(w, p.vertex);
  for (const LightObjectPlan& o : p.lights) light_object(w, o);
  channels(w, p);
  texgens(w, p);
  tev(w, p);
  pixel_engine(w, p.pixel);
  return std::move(w.body);
}

}  // namespace

GeneratedPrograms emit_programs(const ScenePlan& plan) {
  GeneratedPrograms out;
  for (const MaterialPlan& m : plan.materials) {
    for (const ArrayPlan& a : m.arrays) {
      Declaration d;
      d.type = Declaration::Type::ByteArray;
      d.name = a.name;
      d.values.assign(a.bytes.begin(), a.bytes.end());
      out.file.top_level.push_back(Statement::of(std::move(d), a.what));
    }
    for (size_t p = 0; p < m.passes.size(); ++p) {
      Function f;
      f.name = pass_function_name(m.c_name, static_cast<int>(p));
      const std::string note = describe_pass(m.passes[p]);
      f.comment = "Material " + m.name + ", pass " + std::to_string(p) + ": " + note;
      f.body = pass_body(m.passes[p]);
      out.notes[f.name] = note;
      out.file.functions.push_back(std::move(f));
    }
  }
  return out;
}

}  // namespace lt::gx
