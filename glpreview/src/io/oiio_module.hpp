// The OpenImageIO module: the image formats and the text drawing that only OpenImageIO provides here (environment
// images other than EXR, such as Radiance .hdr; the QA sheet's labels), in a library of its own
// (libmetalfit_glpreview_oiio.so, sources in oiio/) that glpreview loads with dlopen on first use, so that a run
// reading and writing only EXR and PNG never loads OpenImageIO and the libraries it pulls in.
#pragma once

#include <string>
#include <vector>

#include "glpreview/io/image.hpp"
#include "glpreview/io/image_text.hpp"

namespace metalfit::glpreview {

// What the module exports (built with the same compiler and standard library as glpreview, in the same build).
struct OiioModuleApi {
    static constexpr int kVersion = 2;
    int version = kVersion;
    // Reads any image OpenImageIO reads as RGB (a grey image expanded, alpha dropped), after checking the header's
    // dimensions; with `header_only`, only the header (image gets its width and height, no pixels). Empty on success,
    // else the one-line reason (to follow "FILE: ").
    std::string (*read_rgb)(const char* file, Image& image, bool header_only) = nullptr;
    // Draws the boxes as draw_text (image_text.hpp) says. Empty on success, else why (to follow "font DejaVuSans: ").
    std::string (*draw_text)(Image& image, const std::vector<TextBox>& boxes) = nullptr;
};

// The entry point's name in the module: extern "C" const OiioModuleApi* metalfit_glpreview_oiio_module().
inline constexpr const char* kOiioModuleEntry = "metalfit_glpreview_oiio_module";

// The module, loaded on the first call: beside the running executable (the build tree's bin/), else in
// <bindir>/../<libdir>/metalfit relative to it (an install, also moved), else in the install's <libdir>/metalfit. Throws std::runtime_error (exit code 1), one line
// naming the places looked at, when it is missing or does not load.
const OiioModuleApi& oiio_module();

}  // namespace metalfit::glpreview
