// Internal: metalfit's own OCIO config (data/ocio/config.ocio, written by scripts/make-ocio-config.py) built through
// OCIO's API, for load_ocio_config when a config file holds exactly the shipped bytes.
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <filesystem>
#include <string_view>

namespace metalfit::detail {

// The bytes of data/ocio/config.ocio at build time.
std::string_view shipped_ocio_config_text();

// The config those bytes describe, as OCIO::Config::CreateFromFile would read it from a file in `folder` (its working
// folder): the same colour spaces, aliases, roles, displays, views and transforms in the same order, so that its
// serialisation equals the parsed file's (test OcioConfigLoad.ShippedConfigBuiltEqualsParsed). Without YAML: OCIO's
// parse of these 8.9 kB costs 17 M instructions, the build a small part of it.
OCIO_NAMESPACE::ConstConfigRcPtr build_shipped_ocio_config(const std::filesystem::path& folder);

}  // namespace metalfit::detail
