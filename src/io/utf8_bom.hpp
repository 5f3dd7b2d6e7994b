#pragma once
// A UTF-8 byte-order mark (EF BB BF), as Windows editors save "UTF-8" text files, is not part of
// the text: every reader of a text file drops it from the start of the first line.
#include <string>

namespace pound {

/// Removes a UTF-8 byte-order mark from the start of `text`; true when there was one.
inline bool strip_utf8_bom(std::string& text) {
  if (text.compare(0, 3, "\xEF\xBB\xBF") != 0) return false;
  text.erase(0, 3);
  return true;
}

}  // namespace pound
