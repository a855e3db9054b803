// Internal: the "WxH" text of a size (image, chessboard) in the vision module's messages.
#pragma once

#include <string>

namespace hecal::vision::internal {

// "640x480" for width 640 and height 480.
inline std::string SizeText(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace hecal::vision::internal
