// A small 3-vector of doubles for scene geometry and the CPU ray tracer (GLSL's vec3 on the GPU side).
#pragma once

#include <cmath>

namespace metalfit::glpreview {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    double operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
    double& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3 operator*(Vec3 a, double s) { return s * a; }
inline Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return (1.0 / length(a)) * a; }
// Mirror direction of incident direction d about unit normal n (GLSL reflect()).
inline Vec3 reflect(Vec3 d, Vec3 n) { return d - 2.0 * dot(d, n) * n; }

// A sphere that bounds an object (its centre and radius).
struct BoundingSphere {
    Vec3 centre;
    double radius = 0;
};

}  // namespace metalfit::glpreview
