#pragma once
// Why libpng or libjpeg-turbo refused a picture, in words a reader can act on
// (chapter 09's textures, chapter 10's glTF images): the decoders speak of
// their own workings ("IEND: out of place", "Invalid IHDR data",
// "Unsupported color conversion request", "Empty JPEG image (DNL not
// supported)"). Private to image_decode.cpp.

#include <string>

namespace vkt::image_detail {

// libpng's error `message`, with the last warning it gave before it (libpng
// warns with the reason, "Image width is zero in IHDR", then fails with
// "Invalid IHDR data"); empty `warning` if none.
std::string png_reason(const std::string& message, const std::string& warning);

// libjpeg-turbo's error `code` (J_MESSAGE_CODE) and its text, for a JPEG whose
// colour space (J_COLOR_SPACE) is `color_space` with `components` channels.
std::string jpeg_reason(int code, const std::string& text, int color_space, int components);

}  // namespace vkt::image_detail
