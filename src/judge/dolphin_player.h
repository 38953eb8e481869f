// judge/: implementations that are not ltrender's, used to judge a path. Here Dolphin, the
// GameCube/Wii emulator: its FIFO player plays a recorded frame (a .dff FIFO log) through its
// software renderer, the bit-level model the gx path follows, and dumps what the video
// interface shows. docs/dolphin-judge.md is the user's side of it.
//
// What a play gives, measured with Debian's dolphin-emu 5.0-17995 and read in
// Dolphin's source:
//  - The frame a log's EFB copy writes to the XFB is shown (and dumped) only at the next video
//    field: the copy points the faked video interface at the XFB [DHW BPStructs.cpp
//    BPMEM_TRIGGER_EFB_COPY -> VideoInterface::FakeVIUpdate], and the field begins while the
//    player writes the following frame, whose FIFO bytes carry one frame's time of core timing
//    [DHW FifoPlayer.cpp WriteFifo]. After the last frame the player powers down when
//    LoopReplay is off [DHW FifoPlayer.cpp AdvanceFrame], so the LAST frame of a log is never
//    dumped, and depending on where the first field falls the first frame may not be either:
//    N frames gave N-1 dumps (frames 0..N-2) at 320x240 and 640x480, N-2 (frames 1..N-2) at
//    160x120 and 304x200, and a 1-frame log none. A log that repeats its frame 3 or more times
//    always gets a dump; take the last.
//  - A dump is the XFB scaled to the 4:3 a FIFO log's video interface reports [DHW
//    VideoInterface.cpp GetAspectRatio "we don't know the correct ratio for fifos"], then cut
//    to multiples of 4 [DHW RenderBase.cpp CalculateOutputDimensions, DumpCurrentFrame
//    ScaleTexture]; and the video interface reads whole 16-pixel words a line [DHW
//    VideoInterface.cpp FakeVIUpdate WPL = fb_width / 16]. So only a 4:3 XFB whose width is a
//    multiple of 16 comes out as it is: 320x240 -> 320x240, 640x480 -> 640x480, but 400x240 ->
//    400x300, 304x200 -> 304x228, 640x528 -> 704x528, resampled.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"

namespace lt::judge {

struct DolphinOptions {
  // Wall-clock bound on the whole play, the X server's start included. Past it Dolphin gets
  // SIGINT (its clean stop), then SIGKILL.
  double deadline_seconds = 60;
  // Then (or after the last frame) Dolphin gets SIGINT, which its nogui front end answers with a
  // clean shutdown; whatever of the play has not ended this many seconds later is killed.
  double stop_grace_seconds = 3;
  std::string executable = "/usr/games/dolphin-emu-nogui";
  std::string xvfb = "Xvfb";  // a name looked up in $PATH, or a path
};

// Environment variable: set to 1, the session's directory (Dolphin's user directory, its
// config, log and frame dumps) is kept and its path printed on stderr.
inline constexpr const char* kKeepDolphinDirVariable = "LTRENDER_KEEP_DOLPHIN_DIR";
// Every process a play starts carries LTRENDER_DOLPHIN_SESSION=<session directory> in its
// environment (and passes it on), so a stray one can be found (the tests look for them).
inline constexpr const char* kDolphinSessionVariable = "LTRENDER_DOLPHIN_SESSION";

// Plays the FIFO log in Dolphin's software renderer under a private Xvfb, in a temporary
// directory, and returns every frame Dolphin dumped, in order (RGB, alpha 1, top row first).
// Throws InputError with one line naming what failed, quoting the end of Dolphin's output or
// log when there is one: Dolphin or Xvfb missing, the deadline passed, Dolphin failed or
// crashed, or no frame was dumped. No process and no directory of the play is left behind.
std::vector<Image> play_fifo_log(const std::filesystem::path& dff, const DolphinOptions& options);
// The same for a log held in memory (written into the session directory first).
std::vector<Image> play_fifo_log(const std::vector<std::uint8_t>& dff,
                                 const DolphinOptions& options);

// Whether Dolphin dumps an XFB of width x height at that size (see above): a 4:3 size whose
// width is a multiple of 16.
bool dumped_unscaled(int width, int height);

}  // namespace lt::judge
