// The sRGB transfer function's decoding (IEC 61966-2-1, the EOTF glTF names for base colour
// textures [glTF 2.0 spec 3.9.2 Metallic-Roughness Material]: "8-bit values encoded with the sRGB
// opto-electronic transfer function ... MUST be decoded to real linear values").
#pragma once

namespace lt {

// An encoded value in [0, 1] (an 8-bit sample v read as v / 255) to linear light, in double:
// v / 12.92 up to 0.04045, ((v + 0.055) / 1.055)^2.4 above.
double srgb_to_linear(double encoded);

}  // namespace lt
