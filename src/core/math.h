#pragma once
#include <cmath>
#include <cstdint>

#include "core/platform.h"

namespace candela {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 0.31830988618379067154f;
constexpr float kInf = 3.402823466e+38f;

struct Vec2 {
  float x = 0, y = 0;
};

struct Vec3 {
  float x = 0, y = 0, z = 0;
  CANDELA_FN float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

// RGBA texels, and tangents as (direction, bitangent sign) the way glTF and MikkTSpace store them.
struct Vec4 {
  float x = 0, y = 0, z = 0, w = 0;
};

CANDELA_FN Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
CANDELA_FN Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
CANDELA_FN Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
CANDELA_FN Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
CANDELA_FN Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
CANDELA_FN Vec3 operator*(float s, Vec3 a) { return a * s; }
CANDELA_FN Vec3 operator/(Vec3 a, float s) { return a * (1.0f / s); }
CANDELA_FN Vec3& operator+=(Vec3& a, Vec3 b) { return a = a + b; }
CANDELA_FN Vec3& operator*=(Vec3& a, Vec3 b) { return a = a * b; }
CANDELA_FN Vec3& operator*=(Vec3& a, float s) { return a = a * s; }

CANDELA_FN float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
CANDELA_FN Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
CANDELA_FN float length(Vec3 a) { return sqrtf(dot(a, a)); }
CANDELA_FN Vec3 normalize(Vec3 a) { return a / length(a); }
CANDELA_FN float maxComponent(Vec3 a) { return fmaxf(a.x, fmaxf(a.y, a.z)); }
CANDELA_FN float luminance(Vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }
CANDELA_FN bool isBlack(Vec3 c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f; }
CANDELA_FN bool isFinite(float x) {
#if defined(__CUDA_ARCH__)
  return isfinite(x);
#else
  return std::isfinite(x);
#endif
}
CANDELA_FN bool isFinite(Vec3 c) { return isFinite(c.x) && isFinite(c.y) && isFinite(c.z); }
CANDELA_FN float sqr(float x) { return x * x; }
CANDELA_FN float clampf(float x, float lo, float hi) { return fminf(fmaxf(x, lo), hi); }
CANDELA_FN float lerp(float t, float a, float b) { return a + t * (b - a); }
CANDELA_FN Vec3 lerp(float t, Vec3 a, Vec3 b) { return a + (b - a) * t; }
CANDELA_FN Vec3 faceForward(Vec3 n, Vec3 v) { return dot(n, v) < 0.0f ? -n : n; }

// Row-major 3x4 affine transform: the layout Embree and OptiX instances take.
struct Affine3x4 {
  float m[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

  CANDELA_FN Vec3 point(Vec3 p) const {
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
            m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
  }
  CANDELA_FN Vec3 vector(Vec3 v) const {
    return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
            m[8] * v.x + m[9] * v.y + m[10] * v.z};
  }
  // Of the 3x3 linear part: negative for transforms that mirror.
  CANDELA_FN float determinant() const {
    return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
           m[2] * (m[4] * m[9] - m[5] * m[8]);
  }
};

// Orthonormal basis around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
struct Frame {
  Vec3 s, t, n;

  CANDELA_FN static Frame fromNormal(Vec3 n) {
    float sign = copysignf(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    return {{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
  }
  CANDELA_FN Vec3 toLocal(Vec3 v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  CANDELA_FN Vec3 toWorld(Vec3 v) const { return s * v.x + t * v.y + n * v.z; }
};

struct Ray {
  Vec3 origin;
  Vec3 direction;
  float tMin = 0.0f;
  float tMax = kInf;
};

}  // namespace candela
