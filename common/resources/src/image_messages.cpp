#include "image_messages.hpp"

#include "vkt/core/files.hpp"

// jpeglib.h uses size_t and FILE without including their headers.
#include <jpeglib.h>
#include <cstddef>
#include <cstdio>
// jerror.h's codes (J_MESSAGE_CODE), which jpeglib.h leaves out.
#include <jerror.h>

#include <string_view>

namespace vkt::image_detail {

namespace {

// What each of PNG's critical chunks is, for a reader who never met one.
std::string chunk_words(std::string_view name) {
    if (name == "IHDR") return "its header chunk (IHDR)";
    if (name == "PLTE") return "its palette chunk (PLTE)";
    if (name == "IDAT") return "its pixel data (IDAT)";
    if (name == "IEND") return "its end chunk (IEND)";
    return "its " + std::string(name) + " chunk";
}

}  // namespace

std::string png_reason(const std::string& message, const std::string& warning) {
    // libpng names the chunk it was reading first: "IEND: out of place".
    std::string_view text = message;
    std::string chunk;
    if (text.size() > 6 && text[4] == ':' && text[5] == ' ') {
        chunk = std::string(text.substr(0, 4));
        text.remove_prefix(6);
    }
    if (text == "out of place")
        return chunk_words(chunk) +
               " is out of place: a PNG is its header (IHDR) first, then its palette (PLTE) if "
               "it has one, its pixel data (IDAT) in chunks one after another, and its end "
               "(IEND) last";
    if (message == "Invalid IHDR data") {
        // "Image width is zero in IHDR": the reason, without the chunk's name.
        std::string why = warning;
        if (why.ends_with(" in IHDR")) why.erase(why.size() - 8);
        if (!why.empty() && why[0] >= 'A' && why[0] <= 'Z') why[0] = char(why[0] - 'A' + 'a');
        return "its header chunk (IHDR) is invalid" + (why.empty() ? "" : ": " + printable(why));
    }
    if (text == "CRC error")
        return chunk_words(chunk) + " is damaged: its checksum (CRC) does not match its bytes";
    if (text == "Missing PLTE before IDAT")
        return "it is a palette PNG with no palette (PLTE) before its pixel data (IDAT)";
    if (text == "Not enough image data")
        return "its pixel data (IDAT) ends before the picture's last row";
    if (text == "Too much image data")
        return "its pixel data (IDAT) holds more than the picture's rows";
    if (chunk == "IDAT")  // zlib's words: "invalid distance too far back"
        return "its compressed pixel data (IDAT) is corrupt (" + printable(text) + ")";
    if (!chunk.empty()) return chunk_words(chunk) + ": " + printable(text);
    return printable(message);
}

std::string jpeg_reason(int code, const std::string& text, int color_space, int components) {
    switch (code) {
        case JERR_CONVERSION_NOTIMPL:
            if (color_space == JCS_CMYK || color_space == JCS_YCCK)
                return std::string("it is a ") + (color_space == JCS_CMYK ? "CMYK" : "YCCK") +
                       " JPEG (four inks, for print), which this loader does not convert to RGB: "
                       "save it as an RGB JPEG or a PNG";
            return "its colour space (" + std::to_string(components) +
                   " components) is not one this loader converts to RGB";
        case JERR_EMPTY_IMAGE:
            return "its header gives a height of 0: the height would come after the first scan, "
                   "in a DNL marker, which libjpeg-turbo does not read (save the picture again "
                   "with any encoder)";
        case JERR_INPUT_EOF:
        case JWRN_JPEG_EOF:
        case JWRN_HIT_MARKER:
            return "the file ends before its last pixels (cut short?)";
        case JERR_NO_IMAGE:
            return "no picture in the file: it holds only tables, no frame";
        case JWRN_EXTRANEOUS_DATA:
            return "its data is corrupt: stray bytes between its parts (" + printable(text) + ")";
        default:
            return printable(text);
    }
}

}  // namespace vkt::image_detail
