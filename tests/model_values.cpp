// For ctest export.wgsl_webgpu (wgsl_webgpu.mjs): libfit's own evaluation of the models (Model::evaluate, in double)
// at the constants of shader exports, to compare the shaders' results with.
// Usage: model_values MU...  reads lines "<glsl function> <parameter values, channel by channel: p0 r g b, p1 r g b…>"
// from stdin and prints per line, per mu, the three channels' F(mu) (%.9g), space separated.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "libfit/models/model.hpp"

int main(int argc, char** argv) {
    std::vector<double> mus;
    for (int i = 1; i < argc; ++i) mus.push_back(std::strtod(argv[i], nullptr));
    std::string line;
    int number = 0;
    while (std::getline(std::cin, line)) {
        ++number;
        std::istringstream in(line);
        std::string function;
        in >> function;
        const metalfit::Model* model = nullptr;
        for (const metalfit::Model* m : metalfit::all_models())
            if (m->glsl_function() == function) model = m;
        const std::size_t count = model ? model->parameters().size() : 0;
        std::vector<double> values(count * 3);
        for (double& v : values) in >> v;
        if (!model || !in) {
            std::cerr << "model_values: line " << number << ": '" << line << "' is no model function and its "
                      << count * 3 << " values\n";
            return 1;
        }
        std::string out;
        for (const double mu : mus)
            for (std::size_t c = 0; c < 3; ++c) {
                std::vector<double> channel(count);
                for (std::size_t p = 0; p < count; ++p) channel[p] = values[p * 3 + c];
                char text[32];
                std::snprintf(text, sizeof text, "%.9g", model->evaluate(channel, mu));
                out += (out.empty() ? "" : " ") + std::string(text);
            }
        std::cout << out << '\n';
    }
    return 0;
}
