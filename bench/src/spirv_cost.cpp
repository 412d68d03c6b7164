#include "metalfit_bench/spirv_cost.hpp"

#include <unistd.h>

#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <stdexcept>

#include "metalfit_bench/subprocess.hpp"

namespace metalfit::bench {
namespace {

constexpr std::uint32_t kMagic = 0x07230203;

enum Op : std::uint32_t {
    OpNop = 0,
    OpTypeBool = 20,
    OpTypeInt = 21,
    OpTypeFloat = 22,
    OpTypeVector = 23,
    OpFDiv = 136,
    OpFRem = 140,
    OpFMod = 141,
    OpDot = 148,
    OpLine = 8,
    OpExtInstImport = 11,
    OpExtInst = 12,
    OpFunction = 54,
    OpFunctionParameter = 55,
    OpFunctionEnd = 56,
    OpVariable = 59,
    OpLoopMerge = 246,
    OpSelectionMerge = 247,
    OpLabel = 248,
    OpNoLine = 317,
};

bool is_structural(std::uint32_t op) {
    switch (op) {
        case OpNop:
        case OpLine:
        case OpNoLine:
        case OpFunction:
        case OpFunctionParameter:
        case OpFunctionEnd:
        case OpVariable:
        case OpLabel:
        case OpSelectionMerge:
        case OpLoopMerge: return true;
        default: return false;
    }
}

bool is_arithmetic(std::uint32_t op) { return (op >= 126 && op <= 152) || (op >= 194 && op <= 205); }
bool is_texture(std::uint32_t op) { return (op >= 87 && op <= 99) || (op >= 305 && op <= 315) || op == 320; }
bool is_transcendental_glsl450(std::uint32_t instruction) {
    return (instruction >= 13 && instruction <= 32) || instruction == 66 || instruction == 67 || instruction == 69 ||
           instruction == 72;
}

// The weight of one lane of an instruction (SpirvCounts::weighted, docs/fitting.md "Costs"): a GPU's special-function
// unit runs at a quarter of the FMA rate (NVIDIA: 4 special-function lanes per 16 FP32 lanes; AMD RDNA: quarter
// rate), so an instruction on it weighs 4; a division is a reciprocal there and a multiply (5), exp and log a base-2 one and a
// multiply (5), pow a log2, a multiply and an exp2 (9), the inverse trigonometry about two (8).
double glsl450_weight(std::uint32_t instruction) {
    switch (instruction) {
        case 26: return 9;  // Pow
        case 27:            // Exp
        case 28: return 5;  // Log
        case 29:            // Exp2
        case 30:            // Log2
        case 31:            // Sqrt
        case 32:            // InverseSqrt
        case 13:            // Sin
        case 14: return 4;  // Cos
        case 66:            // Length
        case 67:            // Distance
        case 69:            // Normalize
        case 72: return 4;  // Refract: a root (the dot product is counted by its lanes below)
        default: return is_transcendental_glsl450(instruction) ? 8 : 1;
    }
}

std::string literal_string(std::span<const std::uint32_t> words) {
    std::string s;
    for (std::uint32_t w : words)
        for (int b = 0; b < 4; ++b) {
            const char c = static_cast<char>((w >> (8 * b)) & 0xFF);
            if (c == '\0') return s;
            s += c;
        }
    return s;
}

std::string wrapper(const std::string& functions, const std::string& uniforms, const std::string& body) {
    return "#version 450\n" + functions + "\nlayout(location = 0) in float metalfit_bench_mu;\n" +
           "layout(location = 0) out vec4 metalfit_bench_color;\n" + uniforms +
           "void main() {\n    metalfit_bench_color = vec4(" + body + ", 1.0);\n}\n";
}

std::string uniform_block(std::size_t count) {
    std::string u = "layout(std140, binding = 0) uniform MetalfitBenchParams {";
    for (std::size_t i = 0; i < count; ++i) u += " vec3 metalfit_bench_p" + std::to_string(i) + ";";
    return u + " };\n";
}

}  // namespace

SpirvCounts count_spirv(std::span<const std::uint32_t> words) {
    if (words.size() < 5 || words[0] != kMagic) throw std::runtime_error("not a SPIR-V module (bad header)");
    std::map<std::uint32_t, std::string> ext_sets;
    std::map<std::uint32_t, int> type_lanes;   // scalar and vector type id -> components
    std::map<std::uint32_t, int> value_lanes;  // result id -> components of its type
    SpirvCounts counts;
    bool in_function = false;
    for (std::size_t i = 5; i < words.size();) {
        const std::uint32_t op = words[i] & 0xFFFF, length = words[i] >> 16;
        if (length == 0 || i + length > words.size())
            throw std::runtime_error("malformed SPIR-V: instruction at word " + std::to_string(i) + " is truncated");
        const std::span<const std::uint32_t> inst = words.subspan(i, length);
        i += length;
        if (op == OpExtInstImport && length >= 3) ext_sets[inst[1]] = literal_string(inst.subspan(2));
        if ((op == OpTypeBool || op == OpTypeInt || op == OpTypeFloat) && length >= 2) type_lanes[inst[1]] = 1;
        if (op == OpTypeVector && length >= 4) type_lanes[inst[1]] = static_cast<int>(inst[3]);
        // Lanes of the result (1 for untyped or non-arithmetic types); a dot product works on its operands' lanes.
        int lanes = 1;
        if (length >= 3) {
            const auto t = type_lanes.find(inst[1]);
            if (t != type_lanes.end()) {
                lanes = t->second;
                value_lanes[inst[2]] = lanes;
            }
        }
        if (op == OpDot && length >= 4) {
            const auto v = value_lanes.find(inst[3]);
            lanes = v != value_lanes.end() ? v->second : 1;
        }
        if (op == OpFunction) in_function = true;
        if (op == OpFunctionEnd) in_function = false;
        if (!in_function || is_structural(op)) continue;
        if (op == OpExtInst) {
            if (length < 5) throw std::runtime_error("malformed SPIR-V: short OpExtInst");
            const auto set = ext_sets.find(inst[3]);
            if (set == ext_sets.end() || set->second != "GLSL.std.450")
                ++counts.other;
            else if (is_transcendental_glsl450(inst[4]))
                ++counts.transcendental;
            else
                ++counts.arithmetic;
            if (set != ext_sets.end() && set->second == "GLSL.std.450") {
                const auto operand = length >= 6 ? value_lanes.find(inst[5]) : value_lanes.end();
                const int operand_lanes = operand != value_lanes.end() ? operand->second : lanes;
                // Length, Distance, Normalize, Refract: a dot product over the operand's lanes, then the root.
                const bool reduces = inst[4] == 66 || inst[4] == 67 || inst[4] == 69 || inst[4] == 72;
                counts.weighted += reduces ? operand_lanes + glsl450_weight(inst[4]) : lanes * glsl450_weight(inst[4]);
            }
        } else if (is_arithmetic(op)) {
            ++counts.arithmetic;
            counts.weighted += lanes * (op == OpFDiv || op == OpFRem || op == OpFMod ? 5 : 1);
        } else if (is_texture(op)) {
            ++counts.texture;
            counts.weighted += 4;
        } else {
            ++counts.other;
        }
    }
    return counts;
}

std::string model_fragment_shader(const Model& model) {
    const std::size_t n = model.parameters().size();
    std::string call = std::string(model.glsl_function()) + "(";
    for (std::size_t i = 0; i < n; ++i) call += "metalfit_bench_p" + std::to_string(i) + ", ";
    return wrapper(model.glsl_source(), uniform_block(n), call + "metalfit_bench_mu)");
}

std::string lut_fragment_shader() {
    return wrapper("",
                   "layout(binding = 1) uniform sampler1D metalfit_bench_lut;\n"
                   "layout(std140, binding = 0) uniform MetalfitBenchLut { float metalfit_bench_lut_size; };\n",
                   "texture(metalfit_bench_lut, (metalfit_bench_mu * (metalfit_bench_lut_size - 1.0) + 0.5) / "
                   "metalfit_bench_lut_size).rgb");
}

std::string passthrough_fragment_shader() { return wrapper("", uniform_block(1), "metalfit_bench_p0"); }

std::vector<std::uint32_t> compile_fragment_shader(const std::filesystem::path& validator, const std::string& source) {
    std::random_device random;
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("metalfit-spirv-" + std::to_string(getpid()) + "-" + std::to_string(random()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path frag = dir / "shader.frag", spv = dir / "shader.spv";
    struct Cleanup {
        std::filesystem::path dir;
        ~Cleanup() {
            std::error_code ec;
            std::filesystem::remove_all(dir, ec);
        }
    } cleanup{dir};
    std::ofstream(frag) << source;
    const ProcessResult r = run_process(validator, {"-V", "-Os", "-o", spv.string(), frag.string()});
    if (r.exit_code != 0)
        throw std::runtime_error(validator.filename().string() + " failed: " + last_line(r.out + "\n" + r.err));
    std::ifstream in(spv, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() % 4 != 0) throw std::runtime_error("SPIR-V output is not a whole number of words");
    std::vector<std::uint32_t> words(bytes.size() / 4);
    for (std::size_t w = 0; w < words.size(); ++w)
        for (int b = 0; b < 4; ++b)
            words[w] |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[4 * w + b])) << (8 * b);
    return words;
}

std::vector<SpirvRow> spirv_costs(const std::filesystem::path& validator) {
    std::vector<std::pair<std::string, std::string>> shaders;
    for (const Model* m : all_models()) shaders.emplace_back(std::string(m->id()), model_fragment_shader(*m));
    shaders.emplace_back("reference-lut", lut_fragment_shader());
    shaders.emplace_back("wrapper", passthrough_fragment_shader());
    std::vector<SpirvRow> rows;
    for (const auto& [id, source] : shaders) {
        try {
            rows.push_back({id, count_spirv(compile_fragment_shader(validator, source)), ""});
        } catch (const std::exception& e) {
            rows.push_back({id, std::nullopt, e.what()});
        }
    }
    return rows;
}

}  // namespace metalfit::bench
