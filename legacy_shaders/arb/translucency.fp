!!ARBfp1.0
# arbfp path, fragment program: the equation of model.md per pixel in ARB_fragment_program
# assembly (the SM2 model). Generated per material by src/paths/arbfp/arb_generator.cpp, which
# emits only what the scene uses: one block per light (attenuation only for point lights), the
# view vector and thickness only when the translucency term reads them, ambient only when
# non-zero. Lights are packed four to a register (component x, y, z, w of diffuse0, tv0, lobe0,
# att0; then diffuse1 ...) so the lobe t^p, or its replacement, runs once per group of four.
#
# Inputs from translucency.vp:
#   fragment.texcoord[0]  camera-relative position P (the eye is the origin)
#   fragment.texcoord[1]  interpolated normal (not unit)
#   fragment.texcoord[2]  vertex thickness (only when the material reads it)
#   fragment.texcoord[3+g] pow=mul:vertex only: (lobe * s + a) of light group g, per vertex
#                          (then the fragment program has no t, V, H or lobe of its own)
#
# Variant: {{VARIANT}}
{{NOTES}}
# albedo.w = 1 is the output alpha (coverage for the comparison).
PARAM albedo = {{ALBEDO}};
# guard = (1e6, 1e-12, 1e-6, 1e30), the model's hard-case conventions (src/model/translucency.h):
#  x  RSQ(0) is +inf: clamping the normal's 1/|n| to 1e6 (= 1/kMinNormalLength) keeps the
#     zero-normal mask a multiply of finite values (0 * inf would be NaN).
#  y  kMinNormalLength^2: an interpolated normal shorter than 1e-6 is "no normal" (N = 0).
#  z  kMinAttenuationDenominator: a point light at distance 0 with kc = 0 gives 1e6, never inf.
#  w  clamp of 1/|H| (normalised H only): normalize(0) := 0 because 0 * 1e30 = 0.
PARAM guard = {1e6, 1e-12, 1e-6, 1e30};
{{PARAMS}}
TEMP {{TEMPS}};

# N = n / |n|, or 0 when |n| < 1e-6 (then diffuse = 0 and H = L, as the reference).
DP3 r.x, fragment.texcoord[1], fragment.texcoord[1];
RSQ r.y, r.x;
MIN r.y, r.y, guard.x;
SGE r.z, r.x, guard.y;
MUL r.y, r.y, r.z;
MUL N.xyz, fragment.texcoord[1], r.y;
{{VIEW}}
# Per light: diffuse (and attenuation), then t = saturate(dot(V, -H)) with H = L + N*d.
{{LIGHTS}}
# The lobe t^p for every light of a group at once, then (lobe * s + a).
{{LOBE}}
# sum = ambient_light + sum over lights of color * att * (diffuse + (lobe*s + a) * T).
{{ACCUMULATE}}
MUL result.color.xyz, sum, albedo;
MOV result.color.w, albedo.w;
END
