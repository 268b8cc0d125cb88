#pragma once
// Wide floats for the data-parallel parts of the step: one lane per independent constraint.
// AVX2 gives 8 lanes, SSE2 (every x86-64) 4, and other targets fall back to 1 lane, so the same
// kernels compile everywhere. The build turns AVX2 on when the building machine runs it (see the
// top-level CMakeLists.txt); every translation unit sees the same width.

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define SIMCORE_SIMD_AVX2 1
#elif defined(__SSE2__)
#include <emmintrin.h>
#define SIMCORE_SIMD_SSE2 1
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>

// The kernels pass wide values between small helpers; they must inline to stay in registers.
#define SIMCORE_SIMD_INLINE [[gnu::always_inline]] inline

namespace simcore::simd {

#if defined(SIMCORE_SIMD_AVX2)

inline constexpr int kWidth = 8;

struct FloatW {
    __m256 v;

    SIMCORE_SIMD_INLINE static FloatW zero() { return {_mm256_setzero_ps()}; }
    SIMCORE_SIMD_INLINE static FloatW splat(float x) { return {_mm256_set1_ps(x)}; }
    float lane(int i) const { return v[i]; }
    void setLane(int i, float x) { v[i] = x; }
};
struct MaskW {
    __m256 v;
};

SIMCORE_SIMD_INLINE FloatW operator+(FloatW a, FloatW b) { return {_mm256_add_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator-(FloatW a, FloatW b) { return {_mm256_sub_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator*(FloatW a, FloatW b) { return {_mm256_mul_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator/(FloatW a, FloatW b) { return {_mm256_div_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator-(FloatW a) { return {_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))}; }
SIMCORE_SIMD_INLINE FloatW mulAdd(FloatW a, FloatW b, FloatW c) { return {_mm256_fmadd_ps(a.v, b.v, c.v)}; }  // a * b + c
SIMCORE_SIMD_INLINE FloatW max(FloatW a, FloatW b) { return {_mm256_max_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW min(FloatW a, FloatW b) { return {_mm256_min_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW sqrt(FloatW a) { return {_mm256_sqrt_ps(a.v)}; }
SIMCORE_SIMD_INLINE MaskW operator>(FloatW a, FloatW b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
SIMCORE_SIMD_INLINE MaskW operator<(FloatW a, FloatW b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
SIMCORE_SIMD_INLINE MaskW operator&(MaskW a, MaskW b) { return {_mm256_and_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE bool any(MaskW m) { return _mm256_movemask_ps(m.v) != 0; }
SIMCORE_SIMD_INLINE bool all(MaskW m) { return _mm256_movemask_ps(m.v) == 0xFF; }
SIMCORE_SIMD_INLINE FloatW select(MaskW m, FloatW ifTrue, FloatW ifFalse) { return {_mm256_blendv_ps(ifFalse.v, ifTrue.v, m.v)}; }

// Rows of 8 floats (32-byte aligned) at rows + 8 * index[lane] <-> 8 wide values, one per column.
// The 8 x 8 transpose is its own inverse, so the same shuffle serves both directions.
SIMCORE_SIMD_INLINE void transpose8(__m256 r[8]) {
    const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
    const __m256 t4 = _mm256_unpacklo_ps(r[4], r[5]), t5 = _mm256_unpackhi_ps(r[4], r[5]);
    const __m256 t6 = _mm256_unpacklo_ps(r[6], r[7]), t7 = _mm256_unpackhi_ps(r[6], r[7]);
    const __m256 s0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 s1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 s2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 s3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 s4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 s5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 s6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 s7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
    r[0] = _mm256_permute2f128_ps(s0, s4, 0x20);
    r[1] = _mm256_permute2f128_ps(s1, s5, 0x20);
    r[2] = _mm256_permute2f128_ps(s2, s6, 0x20);
    r[3] = _mm256_permute2f128_ps(s3, s7, 0x20);
    r[4] = _mm256_permute2f128_ps(s0, s4, 0x31);
    r[5] = _mm256_permute2f128_ps(s1, s5, 0x31);
    r[6] = _mm256_permute2f128_ps(s2, s6, 0x31);
    r[7] = _mm256_permute2f128_ps(s3, s7, 0x31);
}

SIMCORE_SIMD_INLINE void gatherRows(const float* rows, const std::int32_t* index, FloatW out[8]) {
    __m256 r[8];
    for (int lane = 0; lane < 8; ++lane) r[lane] = _mm256_load_ps(rows + 8 * index[lane]);
    transpose8(r);
    for (int c = 0; c < 8; ++c) out[c].v = r[c];
}

SIMCORE_SIMD_INLINE void scatterRows(float* rows, const std::int32_t* index, const FloatW in[8]) {
    __m256 r[8];
    for (int c = 0; c < 8; ++c) r[c] = in[c].v;
    transpose8(r);
    for (int lane = 0; lane < 8; ++lane) _mm256_store_ps(rows + 8 * index[lane], r[lane]);
}

#elif defined(SIMCORE_SIMD_SSE2)

inline constexpr int kWidth = 4;

struct FloatW {
    __m128 v;

    SIMCORE_SIMD_INLINE static FloatW zero() { return {_mm_setzero_ps()}; }
    SIMCORE_SIMD_INLINE static FloatW splat(float x) { return {_mm_set1_ps(x)}; }
    float lane(int i) const { return v[i]; }
    void setLane(int i, float x) { v[i] = x; }
};
struct MaskW {
    __m128 v;
};

SIMCORE_SIMD_INLINE FloatW operator+(FloatW a, FloatW b) { return {_mm_add_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator-(FloatW a, FloatW b) { return {_mm_sub_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator*(FloatW a, FloatW b) { return {_mm_mul_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator/(FloatW a, FloatW b) { return {_mm_div_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW operator-(FloatW a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }
SIMCORE_SIMD_INLINE FloatW mulAdd(FloatW a, FloatW b, FloatW c) { return {_mm_add_ps(_mm_mul_ps(a.v, b.v), c.v)}; }
SIMCORE_SIMD_INLINE FloatW max(FloatW a, FloatW b) { return {_mm_max_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW min(FloatW a, FloatW b) { return {_mm_min_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW sqrt(FloatW a) { return {_mm_sqrt_ps(a.v)}; }
SIMCORE_SIMD_INLINE MaskW operator>(FloatW a, FloatW b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE MaskW operator<(FloatW a, FloatW b) { return {_mm_cmplt_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE MaskW operator&(MaskW a, MaskW b) { return {_mm_and_ps(a.v, b.v)}; }
SIMCORE_SIMD_INLINE bool any(MaskW m) { return _mm_movemask_ps(m.v) != 0; }
SIMCORE_SIMD_INLINE bool all(MaskW m) { return _mm_movemask_ps(m.v) == 0xF; }
SIMCORE_SIMD_INLINE FloatW select(MaskW m, FloatW ifTrue, FloatW ifFalse) {
    return {_mm_or_ps(_mm_and_ps(m.v, ifTrue.v), _mm_andnot_ps(m.v, ifFalse.v))};
}

SIMCORE_SIMD_INLINE void gatherRows(const float* rows, const std::int32_t* index, FloatW out[8]) {
    for (int half = 0; half < 2; ++half) {
        __m128 r0 = _mm_load_ps(rows + 8 * index[0] + 4 * half), r1 = _mm_load_ps(rows + 8 * index[1] + 4 * half);
        __m128 r2 = _mm_load_ps(rows + 8 * index[2] + 4 * half), r3 = _mm_load_ps(rows + 8 * index[3] + 4 * half);
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
        out[4 * half + 0].v = r0;
        out[4 * half + 1].v = r1;
        out[4 * half + 2].v = r2;
        out[4 * half + 3].v = r3;
    }
}

SIMCORE_SIMD_INLINE void scatterRows(float* rows, const std::int32_t* index, const FloatW in[8]) {
    for (int half = 0; half < 2; ++half) {
        __m128 r0 = in[4 * half + 0].v, r1 = in[4 * half + 1].v, r2 = in[4 * half + 2].v, r3 = in[4 * half + 3].v;
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
        _mm_store_ps(rows + 8 * index[0] + 4 * half, r0);
        _mm_store_ps(rows + 8 * index[1] + 4 * half, r1);
        _mm_store_ps(rows + 8 * index[2] + 4 * half, r2);
        _mm_store_ps(rows + 8 * index[3] + 4 * half, r3);
    }
}

#else

inline constexpr int kWidth = 1;

struct FloatW {
    float v;

    SIMCORE_SIMD_INLINE static FloatW zero() { return {0.0f}; }
    SIMCORE_SIMD_INLINE static FloatW splat(float x) { return {x}; }
    float lane(int) const { return v; }
    void setLane(int, float x) { v = x; }
};
struct MaskW {
    bool v;
};

SIMCORE_SIMD_INLINE FloatW operator+(FloatW a, FloatW b) { return {a.v + b.v}; }
SIMCORE_SIMD_INLINE FloatW operator-(FloatW a, FloatW b) { return {a.v - b.v}; }
SIMCORE_SIMD_INLINE FloatW operator*(FloatW a, FloatW b) { return {a.v * b.v}; }
SIMCORE_SIMD_INLINE FloatW operator/(FloatW a, FloatW b) { return {a.v / b.v}; }
SIMCORE_SIMD_INLINE FloatW operator-(FloatW a) { return {-a.v}; }
SIMCORE_SIMD_INLINE FloatW mulAdd(FloatW a, FloatW b, FloatW c) { return {a.v * b.v + c.v}; }
SIMCORE_SIMD_INLINE FloatW max(FloatW a, FloatW b) { return {std::max(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW min(FloatW a, FloatW b) { return {std::min(a.v, b.v)}; }
SIMCORE_SIMD_INLINE FloatW sqrt(FloatW a) { return {std::sqrt(a.v)}; }
SIMCORE_SIMD_INLINE MaskW operator>(FloatW a, FloatW b) { return {a.v > b.v}; }
SIMCORE_SIMD_INLINE MaskW operator<(FloatW a, FloatW b) { return {a.v < b.v}; }
SIMCORE_SIMD_INLINE MaskW operator&(MaskW a, MaskW b) { return {a.v && b.v}; }
SIMCORE_SIMD_INLINE bool any(MaskW m) { return m.v; }
SIMCORE_SIMD_INLINE bool all(MaskW m) { return m.v; }
SIMCORE_SIMD_INLINE FloatW select(MaskW m, FloatW ifTrue, FloatW ifFalse) { return m.v ? ifTrue : ifFalse; }

SIMCORE_SIMD_INLINE void gatherRows(const float* rows, const std::int32_t* index, FloatW out[8]) {
    for (int c = 0; c < 8; ++c) out[c].v = rows[8 * index[0] + c];
}

SIMCORE_SIMD_INLINE void scatterRows(float* rows, const std::int32_t* index, const FloatW in[8]) {
    for (int c = 0; c < 8; ++c) rows[8 * index[0] + c] = in[c].v;
}

#endif

// Three wide floats: the same vector in every lane's own constraint.
struct Vec3W {
    FloatW x, y, z;
};

SIMCORE_SIMD_INLINE Vec3W operator+(const Vec3W& a, const Vec3W& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
SIMCORE_SIMD_INLINE Vec3W operator-(const Vec3W& a, const Vec3W& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
SIMCORE_SIMD_INLINE Vec3W operator*(const Vec3W& a, FloatW s) { return {a.x * s, a.y * s, a.z * s}; }
SIMCORE_SIMD_INLINE FloatW dot(const Vec3W& a, const Vec3W& b) { return mulAdd(a.x, b.x, mulAdd(a.y, b.y, a.z * b.z)); }
SIMCORE_SIMD_INLINE Vec3W cross(const Vec3W& a, const Vec3W& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
SIMCORE_SIMD_INLINE Vec3W mulAdd(const Vec3W& a, FloatW s, const Vec3W& c) {  // a * s + c
    return {mulAdd(a.x, s, c.x), mulAdd(a.y, s, c.y), mulAdd(a.z, s, c.z)};
}

// A symmetric 3x3 matrix (inverse inertia), six wide floats.
struct SymMat3W {
    FloatW xx, yy, zz, xy, xz, yz;
};

SIMCORE_SIMD_INLINE Vec3W operator*(const SymMat3W& m, const Vec3W& v) {
    return {mulAdd(m.xx, v.x, mulAdd(m.xy, v.y, m.xz * v.z)), mulAdd(m.xy, v.x, mulAdd(m.yy, v.y, m.yz * v.z)),
            mulAdd(m.xz, v.x, mulAdd(m.yz, v.y, m.zz * v.z))};
}

}  // namespace simcore::simd
