// Assimp's warnings about data it changed while importing (a 3DS face naming a vertex past the
// mesh's, which Assimp clamps to the last vertex), as load warnings in the user's terms. Assimp
// reports them only to its global logger; a stream attached to it once routes each message to
// the capture open on the thread that logged it, so imports on several threads stay apart.
#pragma once
#include <string>
#include <vector>

namespace zraster::io {

class AssimpWarnings {
  public:
    // Captures the Assimp warnings logged on this thread until destroyed (one import).
    AssimpWarnings();
    ~AssimpWarnings();
    AssimpWarnings(const AssimpWarnings&) = delete;
    AssimpWarnings& operator=(const AssimpWarnings&) = delete;

    // The captured warnings that mean the scene differs from the file, one line each (with a
    // count when repeated), in the order first seen. Assimp's other messages are about its
    // internals and are left out.
    std::vector<std::string> take();

  private:
    std::vector<std::string> messages_;
    std::vector<std::string>* outer_;
};

}  // namespace zraster::io
