// giflib reading a GIF from memory: the independent decoder the GIF tests read koppel's files
// back with (DGifOpen(&source, ReadGifBytes, &error)).
#pragma once

#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace koppel::test {

struct GifSource {
  const std::string* bytes;
  size_t at = 0;
};

// giflib's InputFunc: the next n bytes of the GifSource in gif->UserData (fewer at the end).
inline int ReadGifBytes(GifFileType* gif, GifByteType* out, int n) {
  GifSource* s = static_cast<GifSource*>(gif->UserData);
  const size_t k = std::min(static_cast<size_t>(n), s->bytes->size() - s->at);
  std::memcpy(out, s->bytes->data() + s->at, k);
  s->at += k;
  return static_cast<int>(k);
}

}  // namespace koppel::test
