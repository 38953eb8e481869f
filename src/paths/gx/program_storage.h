// The variant a program file's frame is drawn with (ScenePrograms::variant): the given gx
// variant, with the vertex storage, format and draw the file declares (gx_state.h
// DeclaredStorage: its GX_SetVtxAttrFmt in the format it draws with, GX_SetVtxDesc and
// GX_SetArray), so `render --program`, `export --format dff --program` and the FIFO log store and
// send the scene's mesh as the file says, through the very storage and :draw= values the variant
// axes give (one representation, one quantiser).
//
// Where both speak (docs/porting-to-the-wii.md "Vertex storage"):
// - an attribute the file declares is stored so; the variant's axis for it must be left at its
//   default or say the same, else one line names both;
// - a file whose GX_VA_POS is GX_INDEX8/16 draws :draw=indexed (or the variant's strips / list,
//   indexed too); a file that sends it GX_DIRECT refuses a variant's indexed :draw=;
// - the format a pass declares GX_VA_POS in is the one it draws with (gx_state.h
//   DeclaredStorage): the variant's :vat= becomes it; a :vat= axis naming another is refused,
//   and so are two passes drawing with different formats (the second's line named);
// - every pass stores the mesh alike (one mesh a frame): two passes declaring an attribute
//   otherwise are refused, naming the second's line.
// A fraction the mesh overflows is refused at the declaration's file:line with vertex_storage's
// own message; a GX_SetArray stride other than the stored element's bytes at its line. Generated
// programs declare nothing of their own: the variant is returned as is.
#pragma once

#include "paths/gx/gx_path.h"

namespace lt::gx {

// Sets programs.variant, and gives each pass's descriptor GX_DIRECT where the file indexes (the
// draw indexes each array as :draw= does). Throws InputError as above.
void apply_program_declarations(const Scene& scene, const GxVariant& given,
                                ScenePrograms& programs);

}  // namespace lt::gx
