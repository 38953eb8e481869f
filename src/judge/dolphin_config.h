// Dolphin's user directory for one play (`dolphin-emu-nogui -u DIR`): the settings that make it
// play a FIFO log unattended with the software renderer, dump every shown frame as a PNG at the
// XFB's own resolution, log to a file, and exit by itself after the last frame.
#pragma once

#include <filesystem>

namespace lt::judge {

// Creates `user_dir` with Config/Dolphin.ini, Config/GFX.ini, Config/Logger.ini and Logs/.
void write_dolphin_user_dir(const std::filesystem::path& user_dir);

// Where Dolphin writes framedump_1.png, framedump_2.png, ... [DHW RenderBase.cpp
// GetFrameDumpNextImageFileName, D_DUMPFRAMES_IDX].
std::filesystem::path frame_dump_dir(const std::filesystem::path& user_dir);

// Dolphin's log file [DHW LogManager.cpp FileLogListener(F_MAINLOG_IDX)].
std::filesystem::path log_file(const std::filesystem::path& user_dir);

}  // namespace lt::judge
