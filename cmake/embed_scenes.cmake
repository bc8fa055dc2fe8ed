# Writes OUTPUT, a C++ source holding the text of every scene file given in
# SCENES (a ;-list), so the binary carries its built-in scenes.
set(body "")
set(names "")
foreach(path IN LISTS SCENES)
  get_filename_component(name "${path}" NAME_WE)
  file(READ "${path}" text)
  string(APPEND body "    {\"${name}\", R\"unfurl_scene(${text})unfurl_scene\"},\n")
endforeach()
file(WRITE "${OUTPUT}.tmp"
"// Generated from assets/scenes by cmake/embed_scenes.cmake; do not edit.
#include <map>
#include <string>

namespace unfurl::sim {
const std::map<std::string, std::string>& builtin_scene_texts() {
  static const std::map<std::string, std::string> texts{
${body}  };
  return texts;
}
}  // namespace unfurl::sim
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
