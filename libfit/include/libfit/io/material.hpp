// Material: measured optical constants plus where they came from.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "libfit/spectral/complex_index.hpp"

namespace metalfit {

struct LayerStack;  // io/layer_stack.hpp

struct Provenance {
    std::filesystem::path file;
    std::string sha256;                             // of the file's bytes
    std::string format;                             // "refractiveindex.info YAML" or "CSV"
    std::string references;                         // REFERENCES (or the catalog's reference, or --reference)
    std::string note;                               // caveat to show beside results (the catalog's note:
                                                    // "DFT calculation, not a measurement"); empty when none
    std::string comments;                           // COMMENTS
    std::map<std::string, std::string> conditions;  // CONDITIONS, values as written
    std::string data_type;                          // e.g. "tabulated nk", "tabulated n + tabulated k"
};

struct Material {
    std::string id;      // catalog id ("Au") or the file stem for user files
    std::string name;    // catalog name ("gold") or the file stem
    std::string source;  // catalog source name ("Johnson") or the file name
    ComplexIndex index;
    Provenance provenance;
    std::vector<std::string> warnings;  // one line each, e.g. "no k data: k = 0 assumed"
    // A film and/or a coat over the material (io/layer_stack.hpp); null: the bare material.
    std::shared_ptr<const LayerStack> layers;
};

}  // namespace metalfit
