// The module's entry point: the table of what it provides (oiio_module.hpp), the only symbol it exports.
#include "module_functions.hpp"

extern "C" __attribute__((visibility("default"))) const metalfit::glpreview::OiioModuleApi*
metalfit_glpreview_oiio_module() {
    static const metalfit::glpreview::OiioModuleApi api{metalfit::glpreview::OiioModuleApi::kVersion,
                                                        metalfit::glpreview::oiio::read_rgb,
                                                        metalfit::glpreview::oiio::draw_text};
    return &api;
}
