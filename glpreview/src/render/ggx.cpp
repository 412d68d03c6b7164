#include "glpreview/render/ggx.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace metalfit::glpreview::ggx {

double smith_lambda(Vec3 w, double alpha) {
    const double z2 = w.z * w.z;
    if (z2 <= 0) return 1e30;
    const double tan2 = std::max(0.0, 1.0 - z2) / z2;
    return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

double smith_g2(Vec3 v, Vec3 l, double alpha) {
    if (v.z <= 0 || l.z <= 0) return 0;
    return 1.0 / (1.0 + smith_lambda(v, alpha) + smith_lambda(l, alpha));
}

double distribution(Vec3 m, double alpha) {
    if (m.z <= 0) return 0;
    const double a2 = alpha * alpha;
    const double d = m.z * m.z * (a2 - 1.0) + 1.0;
    return a2 / (std::numbers::pi * d * d);
}

Vec3 sample_visible_normal(Vec3 v, double alpha, double u1, double u2) {
    const Vec3 vh = normalize(Vec3{alpha * v.x, alpha * v.y, v.z});
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = lensq > 0 ? (1.0 / std::sqrt(lensq)) * Vec3{-vh.y, vh.x, 0} : Vec3{1, 0, 0};
    const Vec3 t2 = cross(vh, t1);
    const double r = std::sqrt(u1);
    const double phi = 2.0 * std::numbers::pi * u2;
    const double p1 = r * std::cos(phi);
    const double s = 0.5 * (1.0 + vh.z);
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize(Vec3{alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)});
}

LobeSample sample_reflection(Vec3 v, double alpha, double u1, double u2) {
    const Vec3 m = sample_visible_normal(v, alpha, u1, u2);
    LobeSample s;
    s.cos_d = std::clamp(dot(v, m), 0.0, 1.0);
    s.l = 2.0 * dot(v, m) * m - v;
    if (s.l.z <= 0) return s;
    if (alpha == 0) {
        s.weight = 1;
        return s;
    }
    const double lambda_v = smith_lambda(v, alpha);
    s.weight = (1.0 + lambda_v) / (1.0 + lambda_v + smith_lambda(s.l, alpha));
    return s;
}

Frame::Frame(Vec3 normal) : n(normal) {
    // Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b2 = n.x * n.y * a;
    t = {1.0 + sign * n.x * n.x * a, sign * b2, -sign * n.x};
    b = {b2, sign + n.y * n.y * a, -n.y};
}

void hammersley(unsigned i, unsigned n, double& u1, double& u2) {
    unsigned bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    u1 = (i + 0.5) / n;
    u2 = bits * 2.3283064365386963e-10;
}

}  // namespace metalfit::glpreview::ggx
