#include "libfit/color/chromaticities.hpp"

namespace metalfit {
namespace {

std::array<double, 2> xy(const XYZ& c) {
    const double sum = c.X + c.Y + c.Z;
    return {c.X / sum, c.Y / sum};
}

}  // namespace

Chromaticities chromaticities_of(const ColorSpaceConverter& space) {
    return {xy(space.to_xyz({1, 0, 0})), xy(space.to_xyz({0, 1, 0})), xy(space.to_xyz({0, 0, 1})),
            xy(space.to_xyz({1, 1, 1}))};
}

}  // namespace metalfit
