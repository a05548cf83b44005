#pragma once
// The sRGB transfer function (IEC 61966-2-1), both ways, on 0..1: what an
// _SRGB format does on every read and write (chapter 03 draws into one;
// chapter 09's textures are stored in one). One definition for the CPU code
// that must do the same: texture mipmaps, the G-buffer's and the deferred
// check's colours, chapter 20's palette.

#include <cmath>

namespace vkt {

inline float srgb_to_linear(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

inline float linear_to_srgb(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

}  // namespace vkt
