#include "glpreview/gl/program_cache.hpp"

namespace metalfit::glpreview {

GLuint ProgramCache::program(const std::vector<ShaderStage>& stages, std::string_view name) {
    std::string key;
    for (const ShaderStage& stage : stages) key += std::to_string(stage.type) + '\n' + stage.source + '\0';
    if (auto it = programs_.find(key); it != programs_.end()) return it->second.id();
    return programs_.emplace(std::move(key), link_program(stages, name)).first->second.id();
}

}  // namespace metalfit::glpreview
