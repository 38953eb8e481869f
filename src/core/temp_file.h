// A private temporary file holding given bytes, removed when it goes out of scope: for the
// libraries that read only by file name (OpenImageIO for a glTF's embedded image, OpenMesh for a
// mesh rewritten in the form its reader follows).
#pragma once

#include <filesystem>
#include <string>

namespace lt {

class TempFile {
 public:
  // Writes `size` bytes to a new "ltrender-<what>.XXXXXX<extension>" in the system's temporary
  // folder (the extension is what the reading library goes by); written() says if that worked.
  TempFile(const std::string& what, const std::string& extension, const void* data,
           std::size_t size);
  ~TempFile();
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  bool written() const { return written_; }

 private:
  std::filesystem::path path_;
  bool written_ = false;
};

}  // namespace lt
