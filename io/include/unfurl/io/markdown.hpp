// Markdown for the reports: free text made safe inside a table cell.
#pragma once

#include <string>

namespace unfurl::io {

// `|` would end the cell and a line break the row.
inline std::string table_cell(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else
      out += c == '\n' ? ' ' : c;
  }
  return out;
}

}  // namespace unfurl::io
