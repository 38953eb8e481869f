#include "judge/dolphin_config.h"

#include <string>

#include "core/fs.h"

namespace lt::judge {

namespace {

// [DHW Core/Config/MainSettings.cpp] names every key (System::Main is Dolphin.ini).
std::string dolphin_ini() {
  return
      // The software renderer: the bit-level model the gx path follows.
      "[Core]\n"
      "GFXBackend = Software Renderer\n"
      // One thread: the FIFO player feeds the GPU from the CPU thread, and in dual core its
      // start can deadlock [DHW FifoPlayer.cpp CPUCore::Init].
      "CPUThread = False\n"
      "[DSP]\n"
      "Backend = No Audio Output\n"
      // No dialog waits for a click that never comes: alerts go to the output instead.
      "[Interface]\n"
      "UsePanicHandlers = False\n"
      "ConfirmStop = False\n"
      "[Analytics]\n"
      "PermissionAsked = True\n"
      "Enabled = False\n"
      // Dump every presented frame, without asking before overwriting [DHW RenderBase.cpp
      // StartFrameDumpToImage].
      "[Movie]\n"
      "DumpFrames = True\n"
      "DumpFramesSilent = True\n"
      // Play the log once and power down after its last frame, which ends Dolphin [DHW
      // FifoPlayer.cpp AdvanceFrame: CPU::State::PowerDown -> WMUserStop].
      "[FifoPlayer]\n"
      "LoopReplay = False\n";
}

// [DHW Core/Config/GraphicsSettings.cpp]: System::GFX is GFX.ini.
std::string gfx_ini() {
  return
      // PNG images rather than a video, at the XFB's resolution rather than the window's
      // [DHW RenderBase.cpp DumpCurrentFrame].
      "[Settings]\n"
      "DumpFramesAsImages = True\n"
      "InternalResolutionFrameDumps = True\n";
}

// [DHW LogManager.cpp]: verbosity 4 is LINFO; the short names of the log types enabled.
std::string logger_ini() {
  return "[Options]\n"
         "Verbosity = 4\n"
         "WriteToFile = True\n"
         "WriteToConsole = False\n"
         "[Logs]\n"
         "BOOT = True\n"
         "COMMON = True\n"
         "CORE = True\n"
         "Video = True\n"
         "VI = True\n";
}

}  // namespace

void write_dolphin_user_dir(const std::filesystem::path& user_dir) {
  std::filesystem::create_directories(user_dir / "Config");
  // Dolphin opens its log file in Logs/ but does not make the folder: without it (measured)
  // there is no log.
  std::filesystem::create_directories(user_dir / "Logs");
  write_text_file(user_dir / "Config" / "Dolphin.ini", dolphin_ini());
  write_text_file(user_dir / "Config" / "GFX.ini", gfx_ini());
  write_text_file(user_dir / "Config" / "Logger.ini", logger_ini());
}

std::filesystem::path frame_dump_dir(const std::filesystem::path& user_dir) {
  return user_dir / "Dump" / "Frames";
}

std::filesystem::path log_file(const std::filesystem::path& user_dir) {
  return user_dir / "Logs" / "dolphin.log";
}

}  // namespace lt::judge
