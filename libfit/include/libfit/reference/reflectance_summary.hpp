// The reflectance of one material at the angles a look-dev TD reads first (F0 = R(1), F82 = R(1/7), R at μ = 0.5,
// 0.25, 0.1), what of it is out of gamut, and the JSON record of it (`metalfit show --json`, schema
// metalfit.show/1, docs/cli.md).
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "libfit/color/color.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/convention.hpp"
#include "libfit/io/material.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit {

struct ReflectanceSample {
    std::string label;  // "F0", "F82", "R(0.5)", ...
    double mu = 0;
    RGB value;
};

struct OutOfGamutValue {
    std::string quantity;  // a sample's label
    int channel = 0;       // 0 red, 1 green, 2 blue
    double value = 0;
};

struct ReflectanceSummary {
    std::vector<ReflectanceSample> samples;     // F0, F82, R(0.5), R(0.25), R(0.1)
    std::vector<OutOfGamutValue> out_of_gamut;  // every sample value outside [0, 1], in sample order
};

ReflectanceSummary summarize_reflectance(const ReferenceCurve& curve);

// The record: material, space, the samples, out-of-gamut values, provenance (file, digest, coverage, colour
// pipeline, the raw white), the material's warnings. Files are named by record_path against `data_dir`.
nlohmann::json reflectance_record(const Material& material, const ReferenceCurve& curve,
                                  const ReflectanceSummary& summary, const Colorimetry& colorimetry,
                                  const OcioConfigChoice& config, const SpectralOptions& spectral,
                                  const std::filesystem::path& data_dir, Convention convention = Convention::metalfit);

}  // namespace metalfit
