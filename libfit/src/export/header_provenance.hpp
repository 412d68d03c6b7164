// Where an exported material's numbers come from, as the lines every export header carries: the data file and its
// hash, the literature reference, the catalog's caveat, the colour pipeline. One list for every format (each format
// only prefixes the lines with its comment syntax), so a new provenance item is one push_back here.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "libfit/fit/fit_record.hpp"
#include "libfit/io/material.hpp"

namespace metalfit::detail {

// One line each, no prefix and no newline: "data source: …", "reference: …", "caveat: …" (only when the material
// has a note), "colour space: …".
// A layered material gets a "stack:" line, a line per layer with its index (n and k at 550 nm, their range over the
// visible) and thickness, and its layers' data files. `base_of_layers`: the constants are the bare metal's, under the
// format's own coat / thin film, and the stack line says so (else: they fit the stack's curve).
std::vector<std::string> header_provenance_lines(const Material& material, const FitRecordContext& record,
                                                 bool base_of_layers = false);

// The identity that opens every per-material JSON document (glTF extras, OpenPBR parameters): `schema`,
// `metalfit_version`, `material`, `name`, `source`, `provenance` (the lines above), `color_space` and `model`, in
// that order; each format appends its own keys after them.
nlohmann::ordered_json material_identity_json(std::string_view schema, const Material& material,
                                              const FitRecordContext& record, std::string_view model,
                                              bool base_of_layers = false);

}  // namespace metalfit::detail
