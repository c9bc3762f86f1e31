#pragma once
// A library opened at run time (dlopen), so that a process loads a heavy
// dependency only when it needs it: OpenGL only when a backend asks for it
// (and only the provider it uses), OpenImageIO only when an image is read,
// written or compared. Libraries stay loaded until the process ends:
// drivers do not unload well.
#include <string>
#include <vector>

namespace snell {

class SharedLibrary {
 public:
  // Tries each file name in order; throws SetupError with `installHint`
  // and dlerror's text when none opens.
  static SharedLibrary open(const std::vector<std::string>& fileNames,
                            const std::string& installHint);

  // nullptr when the library has no such symbol.
  void* symbol(const char* name) const;
  const std::string& fileName() const { return fileName_; }

 private:
  SharedLibrary(void* handle, std::string fileName)
      : handle_(handle), fileName_(std::move(fileName)) {}
  void* handle_ = nullptr;
  std::string fileName_;
};

}  // namespace snell
