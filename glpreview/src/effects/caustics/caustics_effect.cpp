#include "caustics_effect.hpp"

namespace metalfit::glpreview {
namespace {

class CausticsEffect final : public Effect {
public:
    std::string_view name() const override { return "caustics"; }
};

}  // namespace

const Effect& caustics_effect() {
    static const CausticsEffect effect;
    return effect;
}

}  // namespace metalfit::glpreview
