// A scene's frame as the console receives it: per frame the clear, every pass of every material
// in order (the pass's GxState, its objects' vertices, its textures as memory updates), then the
// EFB copy to the XFB - a Dolphin FIFO log (fifo_log.h) encoded from exactly the states the
// emulator runs (gx_path.cpp), on top of GX_Init's state.
//
// Memory map (physical addresses; every block 32-byte aligned and apart from the others):
//   0x00000000-0x0014a000  written by the FIFO player's own initial clearing copy (probe README)
//   0x00200000             the XFB, YUYV 4:2:2, width x height x 2 bytes (<= 0xa5000)
//   0x00800000             the target of each frame's clearing copy, RGBA8 (<= 0x14a000)
//   0x00a00000-0x01000000  vertex arrays and display lists (:draw=indexed, strips, list:
//                          indexed_recording.h), each distinct one once
//   0x01000000-0x01040000  the FIFO ring the log names (fifo_log.h)
//   0x01040000-0x01800000  textures: each distinct one once, in tile order
#pragma once

#include <vector>

#include "gx/fifo/bp_registers.h"
#include "gx/fifo/fifo_log.h"
#include "paths/gx/gx_path.h"

namespace lt::gx::fifo {

inline constexpr u32 kXfbAddress = 0x00200000, kClearCopyAddress = 0x00800000,
                     kTextureBase = 0x01040000, kTextureEnd = kMem1Size;

// The EFB is 640 x 528 pixels [DHW VideoCommon.h EFB_WIDTH, EFB_HEIGHT]; the XFB's stride is
// written in 32-byte lines of 2-byte pixels (GX_SetDispCopyDst: width >> 4 [OGC gx.c L1996]),
// so the width must be a multiple of 16. Throws InputError(`file`, `width_key` / `height_key`,
// ...) naming the size.
void check_frame_size(FrameSize size, const std::string& file,
                      const std::string& width_key = "width",
                      const std::string& height_key = "height");

// One frame of the log: the programs a variant draws the scene with, and the frame's own scene
// where it is another (an animation: the camera and lights of render/camera_path.h; or another
// scene altogether, as the Dolphin tests put many scenes in one log).
struct FrameInput {
  GxVariant variant;
  const ScenePrograms* programs = nullptr;
  const Scene* scene = nullptr;  // nullptr: the scene record_frames is given
};

// The frames in order, each self-contained (it writes GX_Init's state, the camera, then every
// register of every pass), with the header snapshot GX_Init's state (GxState{} and GX_Init's
// other registers). Throws InputError when the textures do not fit the memory map.
FifoLog record_frames(const Scene& scene, const std::vector<FrameInput>& frames, FrameSize size);

// The log Dolphin's FIFO player shows every frame of: Dolphin presents a frame's XFB copy when
// the next frame starts, so the last frame of a log is never dumped (the probe: 4 copies give 3
// dumps); the frames are followed by copies of the last. Measured with three frames of
// different clear colours (Dolphin 5.0-17995, software renderer): framedump_N.png shows frame
// N - 1 (frames counted from 0).
// With one copy, logs of a few hundred kilobytes (three_point_blob, baked_blob at 320x240)
// ended before Dolphin dumped anything: the player powers down after the last frame [DHW
// FifoPlayer.cpp AdvanceFrame], and the first video field may fall after the first frame
// (judge/dolphin_player.h). Three copies left every demo scene dumped; the dumps of the copies
// show the last frame.
inline constexpr int kDolphinTrailingCopies = 3;
FifoLog for_dolphin(FifoLog log);

// An animation for Dolphin: for_dolphin with frame 0 once more in front. Where the first video
// field falls after the first frame (measured: three_point_blob's 8-frame animation at 320x240
// gave 9 dumps of 11 frames) the lead-in is the frame not dumped, so every frame of the
// animation is. The dumps end at the log's last frame but one (the second trailing copy): of D
// dumps, frame k of K is dump D - 2 - K + k (tests/dolphin_judge_test.cpp).
FifoLog for_dolphin_animation(FifoLog log);

// Many frames judged at one Dolphin start (the Dolphin tests): for_dolphin_animation's layout and
// dump rule (frame k of K is dump D - 2 - K + k), but the lead-in and the trailing frames are
// blank: GX_Init's registers, the clear and the display copy, nothing drawn. Dolphin then draws
// K frames, not K + 4 (a seeded scene's frame is ~16 MB of FIFO). A blank frame keeps a copy's
// place among the video fields: the FIFO player spreads every frame, whatever its size, over one
// frame's emulated time [DHW FifoPlayer.cpp WriteFifo: elapsed cycles = bytes written * cycles per
// frame / the frame's FIFO size], and it ends with a display copy as a drawn frame does, so it is
// dumped as one. Measured: the 38 Dolphin tests that judge frames (one log each, 320x240) pass with
// it, each frame at the dump the count gives, and dolphin_pictures checks the blank dumps are where
// it puts them. Users' logs keep the copies (for_dolphin, for_dolphin_animation): a log opened in
// Dolphin shows its frame.
FifoLog for_dolphin_judging(FifoLog log, FrameSize size);

}  // namespace lt::gx::fifo
