// unfurl_meshes DIR: writes the project's generated meshes (OBJ + MTL) into
// DIR; assets/meshes holds them (tests check it is up to date).
#include <cstdio>
#include <fstream>

#include "unfurl/render/mesh_generator.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: unfurl_meshes DIR\n");
    return 64;
  }
  for (const auto& [name, text] : unfurl::render::builtin_mesh_files()) {
    const std::string path = std::string(argv[1]) + "/" + name;
    std::ofstream out(path);
    out << text;
    if (!out) {
      std::fprintf(stderr, "unfurl_meshes: cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("%s\n", path.c_str());
  }
  return 0;
}
