/* hj_ls_deriv.c -- upwind (ENO/WENO) and centered derivatives.
 *
 * The row kernels work on n consecutive nodes of a row along dimension 0
 * and differentiate along an arbitrary stride s, so that every inner loop
 * runs over unit-stride arrays (and vectorises) whatever the direction of
 * the derivative.  First the divided differences D1_{i+k+1/2}, k = -3..2,
 * are stored as six rows; the schemes then read them node by node.
 */
#include "hj_ls_deriv.h"
#include "hj_sys.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const char *const names[HJ_LS_NSCHEMES] = {
    "upwindFirstFirst", "upwindFirstENO2", "upwindFirstENO3a", "upwindFirstENO3b",
    "upwindFirstWENO5a", "upwindFirstWENO5b", "upwindFirstWENO3",
};
static const int orders[HJ_LS_NSCHEMES] = {1, 2, 3, 3, 5, 5, 3};

const char *hj_ls_scheme_name(int scheme)
{
    return scheme >= 0 && scheme < HJ_LS_NSCHEMES ? names[scheme] : NULL;
}

/* The reach of first_differences(kmin, kmax) below: max(-kmin, kmax + 1). */
static const int ghosts[HJ_LS_NSCHEMES] = {1, 2, 3, 3, 3, 3, 2};

int hj_ls_scheme_ghost(int scheme) { return scheme >= 0 && scheme < HJ_LS_NSCHEMES ? ghosts[scheme] : HJ_LS_GHOST; }

int hj_ls_scheme_order(int scheme) { return scheme >= 0 && scheme < HJ_LS_NSCHEMES ? orders[scheme] : 0; }

/* AVX2 clone where the CPU has it (no FMA: results are bitwise the same
 * as the baseline SSE2 code). */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define HJ_LS_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define HJ_LS_CLONES
#endif

/* D[k][i] = D1_{i+k+1/2} for k = kmin..kmax, row k + 3 of w. */
static void first_differences(const double *restrict p, ptrdiff_t s, long n, double dx, double *restrict w, int kmin,
                              int kmax)
{
    const double inv = 1.0 / dx;
    for (int k = kmin; k <= kmax; k++) {
        double *restrict D = w + (size_t)(k + 3) * (size_t)n;
        const double *restrict a = p + k * s, *restrict b = p + (k + 1) * s;
        for (long i = 0; i < n; i++) D[i] = (b[i] - a[i]) * inv;
    }
}

/* Branch-free select c ? a : b on the bits (exact); gcc does not
 * if-convert the nested selections of ENO3 by itself. */
static inline __attribute__((always_inline)) double sel(int c, double a, double b)
{
    uint64_t ua, ub;
    memcpy(&ua, &a, sizeof ua);
    memcpy(&ub, &b, sizeof ub);
    const uint64_t m = (uint64_t)0 - (uint64_t)(c != 0);
    const uint64_t u = (ua & m) | (ub & ~m);
    double r;
    memcpy(&r, &u, sizeof r);
    return r;
}

HJ_LS_CLONES
void hj_ls_upwind_difference_row(const double *p, ptrdiff_t s, long n, double dx, int k, double *D)
{
    const double inv = 1.0 / dx;
    const double *a = p + k * s, *b = p + (k + 1) * s;
    for (long i = 0; i < n; i++) D[i] = (b[i] - a[i]) * inv;
}

/* The smaller in magnitude of two neighbouring divided differences, the
 * right one on a tie.  Ties (equal magnitudes) are where ENO stencil
 * choices can differ between codes: O&F (section 3.3) take the left
 * difference when |D_k| <= |D_k+1|, ToolboxLS's upwindFirstENO2/ENO3a
 * take the left only when it is strictly smaller.  We follow the toolbox,
 * whose kernel paper 2 describes: with O&F's choice the reinitDemo star
 * at 'high' ends 1.5e-3 (relative) from the toolbox's own array, with the
 * toolbox's 1e-11 (paper2_toolbox/toolboxls.c). */
#define AMIN(a, b) (fabs(a) < fabs(b) ? (a) : (b))

/* WENO5, O&F (3.28)-(3.38), by windows.  The five first differences
 * w0..w4 = D1_{c-2}..D1_{c+2} around an interface c serve two
 * derivatives: the left one at the node right of c (v1..v5 = w0..w4) and
 * the right one at the node left of c (v1..v5 = w4..w0, mirrored).  Their
 * epsilon, smoothness indicators (S1 of one is S3 of the other, S2 is
 * shared) and hence weights are the same, computed once per window where
 * a kernel walks the interfaces.  The forms below are invariant under the
 * mirror (the same bits for a, b, c and c, b, a), so that a derivative has
 * the same bits whichever way its window was computed. */

/* S1 (3.32) of v1, v2, v3 = a, b, c and S3 (3.34) of v3, v4, v5 = c, b, a:
 * 13/12 (a - 2b + c)^2 + 1/4 (a - 4b + 3c)^2. */
static inline __attribute__((always_inline)) double smooth_end(double a, double b, double c)
{
    const double t = (a + c) - 2 * b, u = (a + 3 * c) - 4 * b;
    return 13.0 / 12 * t * t + 0.25 * u * u;
}

/* S2 (3.33) of v2, v3, v4 = a, b, c: 13/12 (a - 2b + c)^2 + 1/4 (a - c)^2. */
static inline __attribute__((always_inline)) double smooth_mid(double a, double b, double c)
{
    const double t = (a + c) - 2 * b, u = a - c;
    return 13.0 / 12 * t * t + 0.25 * u * u;
}

static inline __attribute__((always_inline)) double max2(double a, double b) { return b > a ? b : a; }

/* The largest square of the four inner differences of a window pair,
 * max(w1^2..w4^2); a window's m of (3.38) is max2 of it with its fifth
 * square.  The max of a set of numbers does not depend on the order, so
 * any grouping gives the same bits (a NaN in a window makes both its
 * values NaN whatever m is). */
static inline __attribute__((always_inline)) double max4sq(double a, double b, double c, double d)
{
    return max2(max2(a * a, b * b), max2(c * c, d * d));
}

/* 2^-k for eps = f 2^k (1 <= f < 2), from the exponent bits: eps times it
 * is exact.  eps > 0 normal, as (3.38) gives it (>= 1e-99). */
static inline __attribute__((always_inline)) double pow2_inv(double eps)
{
    uint64_t u;
    memcpy(&u, &eps, sizeof u);
    u = UINT64_C(0x7FE0000000000000) - (u & UINT64_C(0x7FF0000000000000));
    double r;
    memcpy(&r, &u, sizeof r);
    return r;
}

/* (a1 c1 + a2 c2 + a3 c3) / (a1 + a2 + a3): the weights' normalisation
 * (3.35)-(3.37) and the blend (3.28). */
static inline __attribute__((always_inline)) double blend3(double a1, double a2, double a3, double c1, double c2,
                                                           double c3)
{
    return (a1 * c1 + a2 * c2 + a3 * c3) / (a1 + a2 + a3);
}

/* Both WENO5 values of the window w0..w4 whose largest square is m: *L
 * from the candidates l1..l3 (c1 of the stencil farthest upwind), *R from
 * r1..r3.  eps is the caller's (epsg >= 0, the toolbox's 'maxOverGrid'),
 * at least 1e-54 (1e-6 m + 1e-99), or 1e-6 m + 1e-99 (3.38).  The floor
 * keeps q_k below 3e61 and the products below 1e246: a caller's eps of
 * 1e-80 (or 0) on data of order 1 overflowed them, NaN at every node;
 * 1e-60 m is below the round-off of any S_k it could change (that S_k
 * is then below 1e-44 m, a linear stretch, whose stencil takes the
 * weight either way), and no eps the library forms reaches it
 * (hj_ls_weno_eps_grid: at least 1e-6 of every window's m).  alpha_k = d_k / (S_k + eps)^2 is multiplied
 * through by the product of the three (S_k + eps)^2, scaled by a power of
 * two near 1/eps^6 (exact): the weights take one division, and since
 * S_k <= 21 m and eps >= 1e-6 m, each q_k is in [1, 5e7]: no overflow,
 * and no underflow even when phi is flat. */
static inline __attribute__((always_inline)) void weno5_pair(double w0, double w1, double w2, double w3, double w4,
                                                            double m, double epsg, double l1, double l2, double l3,
                                                            double r1, double r2, double r3, double *L, double *R)
{
    const double el = 1e-6 * m + 1e-99, eps = sel(epsg >= 0, max2(epsg, 1e-54 * el), el);
    const double k = pow2_inv(eps), e = eps * k;
    double q1 = smooth_end(w0, w1, w2) * k + e, q2 = smooth_mid(w1, w2, w3) * k + e,
           q3 = smooth_end(w4, w3, w2) * k + e;
    q1 *= q1, q2 *= q2, q3 *= q3;
    const double p12 = q1 * q2, p13 = q1 * q3, p23 = q2 * q3;
    /* left: d = 0.1, 0.6, 0.3 on S1, S2, S3; right: S1 and S3 swap */
    *L = blend3(0.1 * p23, 0.6 * p13, 0.3 * p12, l1, l2, l3);
    *R = blend3(0.1 * p12, 0.6 * p13, 0.3 * p23, r1, r2, r3);
}

/* WENO5A in Jiang & Peng's form (SIAM J. Sci. Comput. 21 (2000), 2126,
 * (2.8)-(2.10)).  Node i's left derivative from v1..v5 = D1_{i-5/2}..
 * D1_{i+3/2} and its right one from D1_{i+5/2}..D1_{i-3/2} are
 *   phi_x^-/+ = C_i -/+ Phi(a, b, c, d),  C_i = (-v2 + 7 v3 + 7 v4 - v5)/12,
 * with a..d the second differences of phi / dx on the upwind side: for
 * the left one a = v2 - v1, b = v3 - v2, c = v4 - v3, d = v5 - v4; for
 * the right one the same of the node's right window read backwards
 * (a = dd_{i+2}, .., d = dd_{i-1}, dd_j = D1_{j+1/2} - D1_{j-1/2}).
 *   Phi = 1/3 w0 (a - 2b + c) + 1/6 (w2 - 1/2)(b - 2c + d).
 * Checked symbolically (sympy, expanding both sides): w0 c1 + w1 c2 + w2 c3
 * with O&F's candidates (3.25)-(3.27) (which are WENO5A's ENO3 ones,
 * polynomially equal) and w1 = 1 - w0 - w2 is C - Phi identically; the
 * mirrored right stencil gives C + Phi(dd_{i+2}, .., dd_{i-1}) with the
 * same C_i.  Jiang & Peng's indicators IS0 = 13 (a - b)^2 + 3 (a - 3b)^2,
 * IS1 = 13 (b - c)^2 + 3 (b + c)^2, IS2 = 13 (c - d)^2 + 3 (3c - d)^2
 * are exactly 12 S1, 12 S2, 12 S3 of (3.32)-(3.34); here 4 S_k is formed
 * (13/3 t^2 + u^2: one multiply fewer) and scaled by 1/4 with the power
 * of two that normalises epsilon (exact), so the epsilon (3.38) or the
 * caller's one is the toolbox's, bit for bit, and the weights are the
 * same function (alpha_k scaled by 10, which cancels).  So this is O&F's
 * WENO5 to round-off.  The differences of the indicators also give
 * T1 = (a - b) - (b - c), T2 = (b - c) + (d - c).  In the scaled form, with
 * alpha = (1, 6, 3) / q_k and s their sum,
 *   Phi = (4 alpha0 T1 + (alpha2 - alpha0 - alpha1) T2) / (12 s),
 *   T1 = a - 2b + c, T2 = b - 2c + d,  phi_x^- = (K - N / s) / 12,
 * K = 12 C_i, N = 12 s Phi.  WENO5B keeps O&F's direct candidates with
 * weno5_pair: the other round-off path, as the toolbox has both.
 *
 * A window w0..w4 gives the left derivative of the node right of its
 * centre (a..d = w1 - w0, .., w4 - w3) and the right one of the node
 * left of it (a..d read backwards): the indicators are shared (S1 of one
 * is S3 of the other), so are T1, T2 (the right one's T1 is the left's
 * T2) and 6 p13.  Each expression is odd or even under the mirror
 * w0..w4 -> w4..w0 bit for bit (negation is exact; sums commute), so a
 * derivative has the same bits whichever way its window was read, as in
 * weno5_pair. */

/* 4 S of (3.32)-(3.34) from t, the difference of the two second
 * differences, and u (S1: t = a - b, u = a - 3b; S2: t = b - c, u = b + c;
 * S3: t = d - c, u = d - 3c): 13/3 t^2 + u^2, scaled back by the caller's
 * power of two (exact). */
static inline __attribute__((always_inline)) double jp_s4(double t, double u) { return 13.0 / 3 * t * t + u * u; }

static inline __attribute__((always_inline)) void weno5a_pair(double w0, double w1, double w2, double w3, double w4,
                                                             double m, double epsg, double *L, double *R)
{
    const double a = w1 - w0, b = w2 - w1, c = w3 - w2, d = w4 - w3;
    const double el = 1e-6 * m + 1e-99, eps = sel(epsg >= 0, max2(epsg, 1e-54 * el), el);
    const double k = pow2_inv(eps), e = eps * k, k4 = 0.25 * k;
    /* the t's also give T1 = (a - b) - (b - c) and T2 = (b - c) + (d - c) */
    const double s1 = a - b, s2 = b - c, s3 = d - c;
    double q1 = jp_s4(s1, a - 3 * b) * k4 + e, q2 = jp_s4(s2, b + c) * k4 + e, q3 = jp_s4(s3, d - 3 * c) * k4 + e;
    q1 *= q1, q2 *= q2, q3 *= q3;
    const double p12 = q1 * q2, p13 = q1 * q3, p23 = q2 * q3, a6 = 6 * p13;
    const double t1 = s1 - s2, t2 = s2 + s3; /* T1, T2 of the left one */
    /* left: alpha = p23, 6 p13, 3 p12; right: p12, 6 p13, 3 p23 with T1, T2 swapped */
    const double xl = p23 + a6, al2 = 3 * p12, xr = p12 + a6, ar2 = 3 * p23;
    const double nl = p23 * (4 * t1) + (al2 - xl) * t2, nr = p12 * (4 * t2) + (ar2 - xr) * t1;
    const double kl = 7 * (w2 + w3) - (w1 + w4), kr = 7 * (w1 + w2) - (w0 + w3);
    *L = (kl - nl / (xl + al2)) * (1.0 / 12);
    *R = (kr + nr / (xr + ar2)) * (1.0 / 12);
}

/* WENO3 from v1, v2, v3 (v1 farthest upwind): candidates -v1/2 + 3 v2/2
 * and (v2 + v3)/2, ideal weights 1/3 and 2/3, eps = 1e-6. */
static inline __attribute__((always_inline)) double weno3(double v1, double v2, double v3)
{
    const double eps = 1e-6, s1 = eps + (v2 - v1) * (v2 - v1), s2 = eps + (v3 - v2) * (v3 - v2);
    const double a1 = (1.0 / 3) / (s1 * s1), a2 = (2.0 / 3) / (s2 * s2);
    return (a1 * (1.5 * v2 - 0.5 * v1) + a2 * 0.5 * (v2 + v3)) / (a1 + a2);
}

/* Direct ENO3 candidates, O&F (3.25)-(3.27). */
#define PHI1(v1, v2, v3) ((v1) / 3 - 7 * (v2) / 6 + 11 * (v3) / 6)
#define PHI2(v2, v3, v4) (-(v2) / 6 + 5 * (v3) / 6 + (v4) / 3)
#define PHI3(v3, v4, v5) ((v3) / 3 + 5 * (v4) / 6 - (v5) / 6)

/* WENO5B: weno5_pair's weights on the direct candidates (3.25)-(3.27). */
static inline __attribute__((always_inline)) void weno5b_pair(double w0, double w1, double w2, double w3, double w4,
                                                             double m, double epsg, double *L, double *R)
{
    weno5_pair(w0, w1, w2, w3, w4, m, epsg, PHI1(w0, w1, w2), PHI2(w1, w2, w3), PHI3(w2, w3, w4), PHI1(w4, w3, w2),
               PHI2(w3, w2, w1), PHI3(w2, w1, w0), L, R);
}

/* Divided difference table around node i, scaled so that no dx appears:
 * e2[j] = dx D2_j, f3[j] = 3 dx^2 D3_{j+1/2}.  Comparisons use f3 before
 * the division by 3 so that the direct form can take the same decisions
 * bit for bit. */
#define TABLE                                                                        \
    const double m3 = DV(0), m2 = DV(1), m1 = DV(2), z0 = DV(3), p1 = DV(4), p2 = DV(5);  \
    const double e2m2 = 0.5 * (m2 - m3), e2m1 = 0.5 * (m1 - m2), e20 = 0.5 * (z0 - m1), \
                 e2p1 = 0.5 * (p1 - z0), e2p2 = 0.5 * (p2 - p1);                     \
    const double f3m2 = e2m1 - e2m2, f3m1 = e20 - e2m1, f30 = e2p1 - e20, f3p1 = e2p2 - e2p1;

void hj_ls_upwind_row(int scheme, const double *p, ptrdiff_t s, long n, double dx, double *dl, double *dr, double *w)
{
    hj_ls_upwind_row_eps(scheme, p, s, n, dx, -1, dl, dr, w);
}

/* Row loops: whole blocks of 8 nodes, then the last 8 nodes again
 * instead of a scalar remainder (a scalar node of these kernels costs
 * about what a vector of them does; recomputing a node gives the same
 * bits, the outputs never alias the inputs). */
#define BLOCKS8(N, ...)                                                                    \
    do {                                                                                   \
        const long N_ = (N), n8_ = N_ & ~7L;                                               \
        for (long i = 0; i < n8_; i++) __VA_ARGS__                                         \
        if (n8_ < N_ && N_ >= 8) {                                                         \
            const long b_ = N_ - 8;                                                        \
            for (long i = b_; i < b_ + 8; i++) __VA_ARGS__                                 \
        } else                                                                             \
            for (long i = n8_; i < N_; i++) __VA_ARGS__                                    \
    } while (0)
#define ROWS(...) BLOCKS8(n, __VA_ARGS__)

/* The outputs of node i from its left and right derivatives L, R: L and
 * R (mode 0), or the mean (L + R)/2 and the difference R - L (mode 1, as
 * the Lax-Friedrichs term uses them: the same expressions). */
#define STORE2(i, L, R)                          \
    do {                                         \
        const double l_ = (L), r_ = (R);         \
        if (mode) {                              \
            dl[i] = 0.5 * (l_ + r_);             \
            dr[i] = r_ - l_;                     \
        } else {                                 \
            dl[i] = l_;                          \
            dr[i] = r_;                          \
        }                                        \
    } while (0)

/* The schemes that read the first differences only (ENO3, WENO5,
 * WENO3): D[k][i] = D1_{i+k-3+1/2}, k = 0..5 (WENO3 reads 1..4). */
static inline __attribute__((always_inline)) void upwind_diffs(int mode, int reg, int scheme, const double *const *D,
                                                              const double *p, ptrdiff_t s, double inv, long n,
                                                              double eps, double *restrict dl, double *restrict dr)
{
    /* D1_{i+k-3+1/2}: from the rows D (reg 0) or in registers from the
     * values p along stride s (reg 1), the same expression as
     * first_differences */
#define DV(k) (reg ? (p[i + ((k) - 2) * s] - p[i + ((k) - 3) * s]) * inv : D[k][i])
    switch (scheme) {
    case HJ_LS_ENO3A:
        ROWS({
            TABLE
            /* all candidates, then branch-free selection (vectorises);
             * ties go right, as AMIN */
            const double la = m1 + e2m1 + 2 * (f3m2 / 3), lb = m1 + e2m1 + 2 * (f3m1 / 3);
            const double lc = m1 + e20 - f3m1 / 3, ld = m1 + e20 - f30 / 3;
            const double r3 = z0 - e20 - f3m1 / 3, r2 = z0 - e20 - f30 / 3;
            const double r2b = z0 - e2p1 + 2 * (f30 / 3), r1 = z0 - e2p1 + 2 * (f3p1 / 3);
            const double l1 = sel(fabs(f3m2) < fabs(f3m1), la, lb), l2 = sel(fabs(f3m1) < fabs(f30), lc, ld);
            const double q1 = sel(fabs(f3m1) < fabs(f30), r3, r2), q2 = sel(fabs(f30) < fabs(f3p1), r2b, r1);
            STORE2(i, sel(fabs(e2m1) < fabs(e20), l1, l2), sel(fabs(e20) < fabs(e2p1), q1, q2));
        });
        break;
    case HJ_LS_ENO3B:
        ROWS({
            const double m3 = DV(0), m2 = DV(1), m1 = DV(2), z0 = DV(3), p1 = DV(4), p2 = DV(5);
            /* Undivided differences of the v's: the same decisions as ENO3A. */
            const double u2m1 = m1 - m2, u20 = z0 - m1, u2p1 = p1 - z0;
            const double u3m2 = 0.5 * (m1 - m2) - 0.5 * (m2 - m3), u3m1 = 0.5 * u20 - 0.5 * u2m1;
            const double u30 = 0.5 * u2p1 - 0.5 * u20, u3p1 = 0.5 * (p2 - p1) - 0.5 * u2p1;
            const double c1 = PHI1(m3, m2, m1), c2 = PHI2(m2, m1, z0), c3 = PHI3(m1, z0, p1);
            const double d3 = PHI3(z0, m1, m2), d2 = PHI2(p1, z0, m1), d1 = PHI1(p2, p1, z0);
            const double l1 = sel(fabs(u3m2) < fabs(u3m1), c1, c2), l2 = sel(fabs(u3m1) < fabs(u30), c2, c3);
            const double q1 = sel(fabs(u3m1) < fabs(u30), d3, d2), q2 = sel(fabs(u30) < fabs(u3p1), d2, d1);
            STORE2(i, sel(fabs(u2m1) < fabs(u20), l1, l2), sel(fabs(u20) < fabs(u2p1), q1, q2));
        });
        break;
    /* WENO5: the left derivative from the window D0..D4, the right one
     * from D1..D5 (the halves not needed are dropped by the compiler);
     * the four inner squares are shared */
#define WENO5_NODE(PAIR)                                                              \
    ROWS({                                                                            \
        const double m3 = DV(0), m2 = DV(1), m1 = DV(2), z0 = DV(3), p1 = DV(4), p2 = DV(5); \
        const double in = max4sq(m2, m1, z0, p1);                                     \
        double L, R, x_, y_;                                                          \
        PAIR(m3, m2, m1, z0, p1, max2(in, m3 * m3), eps, &L, &x_);                    \
        PAIR(m2, m1, z0, p1, p2, max2(in, p2 * p2), eps, &y_, &R);                    \
        (void)x_, (void)y_;                                                           \
        STORE2(i, L, R);                                                              \
    })
    case HJ_LS_WENO5A:
        WENO5_NODE(weno5a_pair);
        break;
    case HJ_LS_WENO5B:
        WENO5_NODE(weno5b_pair);
        break;
#undef WENO5_NODE
    case HJ_LS_WENO3:
        ROWS({
            const double m2 = DV(1), m1 = DV(2), z0 = DV(3), p1 = DV(4);
            STORE2(i, weno3(m2, m1, z0), weno3(p1, z0, m1));
        });
        break;
    default:
        break;
    }
}
#undef DV

HJ_LS_CLONES
void hj_ls_upwind_diffs_eps(int scheme, const double *const *D, long n, double eps, int mean, double *restrict dl,
                            double *restrict dr)
{
    if (mean) upwind_diffs(1, 0, scheme, D, NULL, 0, 0, n, eps, dl, dr);
    else upwind_diffs(0, 0, scheme, D, NULL, 0, 0, n, eps, dl, dr);
}

/* hj_ls_weno5_diffs_next_eps's and hj_ls_weno5_row_next_eps's loop, the
 * differences from the rows D (reg 0) or in registers from p along
 * stride s (reg 1, upwind_diffs' expression): a window's m, max(w0^2..w4^2),
 * is the same whichever grouping (max4sq, max2) forms it.  local = 1 (a
 * constant) for eps < 0: O&F's epsilon without a selection per window. */
static inline __attribute__((always_inline)) void weno5_next(int mode, int reg, int local, int scheme,
                                                            const double *const *D, const double *p, ptrdiff_t s,
                                                            double inv, long n, double eps,
                                                            const double *restrict left, double *restrict next,
                                                            double *restrict dl, double *restrict dr)
{
    const double e_ = local ? -1.0 : eps;
#define DV(k) (reg ? (p[i + ((k) - 2) * s] - p[i + ((k) - 3) * s]) * inv : D[k][i])
#define NEXT(PAIR)                                                                               \
    ROWS({                                                                                       \
        const double w1 = DV(1), w2 = DV(2), w3 = DV(3), w4 = DV(4), w5 = DV(5);                 \
        const double in = max4sq(w1, w2, w3, w4);                                                \
        double L, R, x_;                                                                         \
        PAIR(w1, w2, w3, w4, w5, max2(in, w5 * w5), e_, next + i, &R);                           \
        if (left) L = left[i];                                                                   \
        else {                                                                                   \
            const double w0 = DV(0);                                                             \
            PAIR(w0, w1, w2, w3, w4, max2(in, w0 * w0), e_, &L, &x_);                            \
        }                                                                                        \
        (void)x_;                                                                                \
        STORE2(i, L, R);                                                                         \
    })
    if (scheme == HJ_LS_WENO5A) NEXT(weno5a_pair);
    else NEXT(weno5b_pair);
#undef NEXT
#undef DV
}

HJ_LS_CLONES
int hj_ls_weno5_diffs_next_eps(int scheme, const double *const *D, long n, double eps, int mean, const double *left,
                               double *next, double *dl, double *dr)
{
    if (scheme != HJ_LS_WENO5A && scheme != HJ_LS_WENO5B) return 0;
    /* the branches on left and eps hoisted out of the loops */
    if (left && eps < 0) {
        if (mean) weno5_next(1, 0, 1, scheme, D, NULL, 0, 0, n, eps, left, next, dl, dr);
        else weno5_next(0, 0, 1, scheme, D, NULL, 0, 0, n, eps, left, next, dl, dr);
    } else if (mean && left) weno5_next(1, 0, 0, scheme, D, NULL, 0, 0, n, eps, left, next, dl, dr);
    else if (mean) weno5_next(1, 0, 0, scheme, D, NULL, 0, 0, n, eps, NULL, next, dl, dr);
    else if (left) weno5_next(0, 0, 0, scheme, D, NULL, 0, 0, n, eps, left, next, dl, dr);
    else weno5_next(0, 0, 0, scheme, D, NULL, 0, 0, n, eps, NULL, next, dl, dr);
    return 1;
}

HJ_LS_CLONES
int hj_ls_weno5_row_next_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps, int mean,
                             const double *left, double *next, double *dl, double *dr)
{
    if (scheme != HJ_LS_WENO5A && scheme != HJ_LS_WENO5B) return 0;
    const double inv = 1.0 / dx;
    if (left && eps < 0) {
        if (mean) weno5_next(1, 1, 1, scheme, NULL, p, s, inv, n, eps, left, next, dl, dr);
        else weno5_next(0, 1, 1, scheme, NULL, p, s, inv, n, eps, left, next, dl, dr);
    } else if (mean && left) weno5_next(1, 1, 0, scheme, NULL, p, s, inv, n, eps, left, next, dl, dr);
    else if (mean) weno5_next(1, 1, 0, scheme, NULL, p, s, inv, n, eps, NULL, next, dl, dr);
    else if (left) weno5_next(0, 1, 0, scheme, NULL, p, s, inv, n, eps, left, next, dl, dr);
    else weno5_next(0, 1, 0, scheme, NULL, p, s, inv, n, eps, NULL, next, dl, dr);
    return 1;
}

/* WENO5 along the row from its differences w_m = D1_{m-5/2}, m < n + 5,
 * formed in registers from the values p (the expression of
 * first_differences; a row of differences stored and read back at five
 * offsets stalls on loads that straddle stores still in flight): window j
 * (w_j..w_j+4) gives the left derivative of node j and the right one of
 * node j - 1, into L[j] and R[j] (t holds 2 n + 9 doubles); then node
 * i's pair is L[i], R[i + 1].  Half the weights of node by node. */
static inline __attribute__((always_inline)) void weno5_windows(int mode, int local, int scheme,
                                                               const double *restrict p, double inv, long n,
                                                               double eps, double *restrict t,
                                                               double *restrict dl, double *restrict dr)
{
    /* R on a cache line if t is (n + 1 rounded up to 8 doubles after L) */
    double *restrict L = t, *restrict R = t + ((n + 8) & ~7L);
    const double e_ = local ? -1.0 : eps; /* local: weno5_next's */
#define W(m) ((p[(m) - 2] - p[(m) - 3]) * inv)
#define WINDOWS(PAIR)                                                                                 \
    BLOCKS8(n + 1, {                                                                                  \
        const double w0 = W(i), w1 = W(i + 1), w2 = W(i + 2), w3 = W(i + 3), w4 = W(i + 4);          \
        PAIR(w0, w1, w2, w3, w4, max2(max4sq(w1, w2, w3, w4), w0 * w0), e_, L + i, R + i);            \
    });
    if (scheme == HJ_LS_WENO5A) WINDOWS(weno5a_pair)
    else WINDOWS(weno5b_pair)
#undef WINDOWS
#undef W
    ROWS({ STORE2(i, L[i], R[i + 1]); });
}

/* Both one-sided derivatives of a row (mode 0: into dl, dr) or their
 * mean and difference (mode 1: (D- + D+)/2 into dl, D+ - D- into dr). */
static inline __attribute__((always_inline)) void upwind_row(int mode, int scheme, const double *p, ptrdiff_t s, long n,
                                                            double dx, double eps, double *restrict dl,
                                                            double *restrict dr, double *w)
{
    switch (scheme) {
    case HJ_LS_UPWIND_FIRST: {
        /* differences in registers, not through w (same expressions) */
        const double inv = 1.0 / dx;
        const double *restrict a = p - s, *restrict b = p + s;
        ROWS({
            STORE2(i, (p[i] - a[i]) * inv, (b[i] - p[i]) * inv);
        });
        return;
    }
    case HJ_LS_ENO2: {
        const double inv = 1.0 / dx;
        const double *restrict a = p - 2 * s, *restrict b = p - s, *restrict c = p + s, *restrict e = p + 2 * s;
        ROWS({
            const double m2 = (b[i] - a[i]) * inv, m1 = (p[i] - b[i]) * inv, z0 = (c[i] - p[i]) * inv,
                         p1 = (e[i] - c[i]) * inv;
            const double e2m1 = 0.5 * (m1 - m2), e20 = 0.5 * (z0 - m1), e2p1 = 0.5 * (p1 - z0);
            STORE2(i, m1 + AMIN(e2m1, e20), z0 - AMIN(e20, e2p1));
        });
        return;
    }
    case HJ_LS_ENO3A: case HJ_LS_ENO3B: case HJ_LS_WENO5A: case HJ_LS_WENO5B: case HJ_LS_WENO3:
        break;
    default:
        return;
    }
    const double *D[6] = {NULL, NULL, NULL, NULL, NULL, NULL};
    const double inv = 1.0 / dx;
    if (s == 1) {
        /* Along the row the six rows of differences are one row read at
         * six offsets: D1_{i+k+1/2} is w[i + k + 3] (the same expression,
         * computed once instead of six times). */
        if (scheme == HJ_LS_WENO5A || scheme == HJ_LS_WENO5B) {
            if (eps < 0) weno5_windows(mode, 1, scheme, p, inv, n, eps, w, dl, dr);
            else weno5_windows(mode, 0, scheme, p, inv, n, eps, w, dl, dr);
            return;
        }
        for (long m = 0; m < n + 5; m++) w[m] = (p[m - 2] - p[m - 3]) * inv;
        for (int k = 0; k < 6; k++) D[k] = w + k;
        upwind_diffs(mode, 0, scheme, D, p, s, inv, n, eps, dl, dr);
    } else /* across rows: the differences in registers, not through w */
        upwind_diffs(mode, 1, scheme, D, p, s, inv, n, eps, dl, dr);
}

HJ_LS_CLONES
void hj_ls_upwind_row_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps, double *restrict dl,
                          double *restrict dr, double *w)
{
    upwind_row(0, scheme, p, s, n, dx, eps, dl, dr, w);
}

HJ_LS_CLONES
void hj_ls_upwind_row_mean_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps,
                               double *restrict mean, double *restrict diff, double *w)
{
    upwind_row(1, scheme, p, s, n, dx, eps, mean, diff, w);
}

/* upwind_row's first order and ENO2 mean and difference along each of
 * dim dimensions (dim a constant where inlined: the loop unrolls). */
static inline __attribute__((always_inline)) void upwind_rows_mean(int dim, int scheme, const double *p,
                                                                  const ptrdiff_t *s, long n, const double *dx,
                                                                  double *mean, double *diff, size_t dstride)
{
    for (int d = 0; d < dim; d++)
        upwind_row(1, scheme, p, s[d], n, dx[d], -1, mean + (size_t)d * dstride, diff + (size_t)d * dstride, NULL);
}

/* upwind_rows_mean of first order in 3-D as one loop over the row: the
 * node's value loaded once for the three dimensions, one loop's overhead
 * instead of three (the same expressions: the same bits).  Strides and
 * outputs as separate restrict arguments: so gcc vectorises the loop. */
static inline __attribute__((always_inline)) void first_rows_mean3(const double *restrict p, ptrdiff_t s0,
                                                                  ptrdiff_t s1, ptrdiff_t s2, long n, double i0,
                                                                  double i1, double i2, double *restrict m0,
                                                                  double *restrict m1, double *restrict m2,
                                                                  double *restrict d0, double *restrict d1,
                                                                  double *restrict d2)
{
#define MEAN_DIFF(M, D, S, INV)                                              \
    do {                                                                     \
        const double l_ = (p[i] - p[i - S]) * INV, r_ = (p[i + S] - p[i]) * INV; \
        M[i] = 0.5 * (l_ + r_);                                              \
        D[i] = r_ - l_;                                                      \
    } while (0)
    ROWS({
        MEAN_DIFF(m0, d0, s0, i0);
        MEAN_DIFF(m1, d1, s1, i1);
        MEAN_DIFF(m2, d2, s2, i2);
    });
#undef MEAN_DIFF
}

HJ_LS_CLONES
int hj_ls_upwind_rows_mean(int scheme, const double *p, const ptrdiff_t *s, int dim, long n, const double *dx,
                           const double *inv, double *mean, double *diff)
{
    if (scheme != HJ_LS_UPWIND_FIRST && scheme != HJ_LS_ENO2) return 0;
    /* one call for every dimension: a row of 51 nodes takes about as long
     * as a call's dispatch and set-up */
    if (dim == 3 && scheme == HJ_LS_UPWIND_FIRST)
        first_rows_mean3(p, s[0], s[1], s[2], n, inv[0], inv[1], inv[2], mean, mean + n, mean + 2 * n, diff,
                         diff + n, diff + 2 * n);
    else if (dim == 3) upwind_rows_mean(3, HJ_LS_ENO2, p, s, n, dx, mean, diff, (size_t)n);
    else if (scheme == HJ_LS_UPWIND_FIRST) upwind_rows_mean(dim, HJ_LS_UPWIND_FIRST, p, s, n, dx, mean, diff, (size_t)n);
    else upwind_rows_mean(dim, HJ_LS_ENO2, p, s, n, dx, mean, diff, (size_t)n);
    return 1;
}

HJ_LS_CLONES
int hj_ls_upwind_rows_mean_block(int scheme, const double *p, const ptrdiff_t *s, int dim, long n, long nrows,
                                 const double *dx, const double *inv, double *mean, double *diff)
{
    if (scheme != HJ_LS_UPWIND_FIRST && scheme != HJ_LS_ENO2) return 0;
    const size_t bn = (size_t)nrows * (size_t)n;
    for (long b = 0; b < nrows; b++) {
        const double *q = p + b * (dim > 1 ? s[1] : 0);
        double *m = mean + (size_t)b * (size_t)n, *df = diff + (size_t)b * (size_t)n;
        if (dim == 3 && scheme == HJ_LS_UPWIND_FIRST)
            first_rows_mean3(q, s[0], s[1], s[2], n, inv[0], inv[1], inv[2], m, m + bn, m + 2 * bn, df, df + bn,
                             df + 2 * bn);
        else if (dim == 3) upwind_rows_mean(3, HJ_LS_ENO2, q, s, n, dx, m, df, bn);
        else if (scheme == HJ_LS_UPWIND_FIRST) upwind_rows_mean(dim, HJ_LS_UPWIND_FIRST, q, s, n, dx, m, df, bn);
        else upwind_rows_mean(dim, HJ_LS_ENO2, q, s, n, dx, m, df, bn);
    }
    return 1;
}

#undef ROWS
#undef BLOCKS8
#undef STORE2

void hj_ls_upwind_row_select(int scheme, const double *p, ptrdiff_t s, long n, double dx, const double *v, double *out,
                             double *w)
{
    hj_ls_upwind_row_select_eps(scheme, p, s, n, dx, -1, v, out, w);
}

HJ_LS_CLONES
void hj_ls_upwind_row_select_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps,
                                 const double *v, double *restrict out, double *w)
{
    if (scheme != HJ_LS_WENO5A && scheme != HJ_LS_WENO5B && scheme != HJ_LS_WENO3) {
        /* cheap schemes: both sides, then select */
        double *dl = w + (size_t)6 * (size_t)n, *dr = dl + n;
        hj_ls_upwind_row_eps(scheme, p, s, n, dx, eps, dl, dr, w + (size_t)8 * (size_t)n);
        for (long i = 0; i < n; i++) {
            const double l = dl[i], r = dr[i]; /* unconditional loads: vectorises */
            out[i] = v[i] > 0 ? l : r;
        }
        return;
    }
    const double *D[6];
    if (s == 1) {
        /* along the row: one row of differences, read at six offsets */
        const double inv = 1.0 / dx;
        for (long m = 0; m < n + 5; m++) w[m] = (p[m - 2] - p[m - 3]) * inv;
        for (int k = 0; k < 6; k++) D[k] = w + k;
    } else {
        for (int k = 0; k < 6; k++) D[k] = w + (size_t)k * (size_t)n;
        first_differences(p, s, n, dx, w, -3, 2);
    }
    hj_ls_upwind_select_diffs_eps(scheme, D, n, eps, v, out);
}

void hj_ls_upwind_select_diffs(int scheme, const double *const *D, long n, const double *v, double *out)
{
    hj_ls_upwind_select_diffs_eps(scheme, D, n, -1, v, out);
}

/* The selected side of nodes I0 + q, q < CNT (a constant 8 leaves no
 * remainder loop).  The right derivative is the left formula on the
 * mirrored stencil (p2, p1, z0, m1, m2, m3): bitwise the same as
 * hj_ls_upwind_row.  One loop per scheme with branch-free selects, so that
 * it vectorises. */
#define MIRROR                                                                                           \
    const int left = v[i] > 0;                                                                           \
    const double a0 = D[0][i], a1 = D[1][i], a2 = D[2][i], a3 = D[3][i], a4 = D[4][i], a5 = D[5][i];     \
    const double m3 = left ? a0 : a5, m2 = left ? a1 : a4, m1 = left ? a2 : a3;                          \
    const double z0 = left ? a3 : a2, p1 = left ? a4 : a1;
#define SELECT_LOOP(I0, CNT)                                                                                   \
    do {                                                                                                       \
        const long i0_ = (I0);                                                                                 \
        if (scheme == HJ_LS_WENO5A)                                                                            \
            for (long i = i0_; i < i0_ + (CNT); i++) {                                                         \
                MIRROR                                                                                         \
                double r_;                                                                                     \
                weno5a_pair(m3, m2, m1, z0, p1, max2(max4sq(m2, m1, z0, p1), m3 * m3), eps, out + i, &r_);    \
                (void)r_;                                                                                      \
            }                                                                                                  \
        else if (scheme == HJ_LS_WENO5B)                                                                       \
            for (long i = i0_; i < i0_ + (CNT); i++) {                                                         \
                MIRROR                                                                                         \
                double r_;                                                                                     \
                weno5b_pair(m3, m2, m1, z0, p1, max2(max4sq(m2, m1, z0, p1), m3 * m3), eps, out + i, &r_);    \
                (void)r_;                                                                                      \
            }                                                                                                  \
        else                                                                                                   \
            for (long i = i0_; i < i0_ + (CNT); i++) {                                                         \
                MIRROR(void) m3, (void)p1;                                                                     \
                out[i] = weno3(m2, m1, z0);                                                                    \
            }                                                                                                  \
    } while (0)

HJ_LS_CLONES
void hj_ls_upwind_select_diffs_eps(int scheme, const double *const *D, long n, double eps, const double *v,
                                   double *restrict out)
{
    /* Whole blocks of 8 nodes, then the last 8 nodes again rather than a
     * scalar remainder: a scalar WENO node costs about what a vector of
     * them does, and recomputing a node gives the same bits. */
    const long n8 = n & ~7L;
    SELECT_LOOP(0, n8);
    if (n8 < n && n >= 8) SELECT_LOOP(n - 8, 8);
    else if (n8 < n) SELECT_LOOP(n8, n - n8);
}
#undef SELECT_LOOP
#undef MIRROR

/* The upwind WENO5 value of node i along one dimension for velocity v:
 * the left derivative from D0..D4 where v > 0, else the right one from
 * the mirrored D5..D1 (MIRROR's expressions, the same bits). */
static inline __attribute__((always_inline)) double weno5_upwind(int scheme, const double *restrict const *D, long i,
                                                                double v, double eps)
{
    const int left = v > 0;
    const double a0 = D[0][i], a1 = D[1][i], a2 = D[2][i], a3 = D[3][i], a4 = D[4][i], a5 = D[5][i];
    const double m3 = left ? a0 : a5, m2 = left ? a1 : a4, m1 = left ? a2 : a3;
    const double z0 = left ? a3 : a2, p1 = left ? a4 : a1;
    const double m = max2(max4sq(m2, m1, z0, p1), m3 * m3);
    double L, R;
    if (scheme == HJ_LS_WENO5A) weno5a_pair(m3, m2, m1, z0, p1, m, eps, &L, &R);
    else weno5b_pair(m3, m2, m1, z0, p1, m, eps, &L, &R);
    (void)R;
    return L;
}

/* hj_ls_weno5_transport2_eps's loop over nodes I0 .. I0 + CNT - 1 for
 * the dimensions with flow (f0, f1 constants where inlined); local: both
 * epsilons are (3.38)'s, so that the selection of eps folds away. */
static inline __attribute__((always_inline)) void weno5_transport2(int scheme, int f0, int f1, int local,
                                                                  const double *const *D0, const double *const *D1,
                                                                  long i0, long cnt, const double *eps,
                                                                  const double *restrict v0,
                                                                  const double *restrict v1, double *restrict out)
{
    const double *restrict A[6], *restrict B[6];
    for (int k = 0; k < 6; k++) A[k] = f0 ? D0[k] : NULL, B[k] = f1 ? D1[k] : NULL;
    const double e0 = local ? -1.0 : eps[0], e1 = local ? -1.0 : eps[1];
    for (long i = i0; i < i0 + cnt; i++) {
        double ac = 0;
        if (f0) ac = 0.0 - v0[i] * weno5_upwind(scheme, A, i, v0[i], e0);
        if (f1) ac = (f0 ? ac : 0.0) - v1[i] * weno5_upwind(scheme, B, i, v1[i], e1);
        out[i] = ac;
    }
}

/* Whole blocks of 8 nodes, then the last 8 again (as the select loop). */
static inline __attribute__((always_inline)) void weno5_transport2_row(int scheme, int f0, int f1, int local,
                                                                      const double *const *D0,
                                                                      const double *const *D1, long n,
                                                                      const double *eps, const double *v0,
                                                                      const double *v1, double *out)
{
    const long n8 = n & ~7L;
    weno5_transport2(scheme, f0, f1, local, D0, D1, 0, n8, eps, v0, v1, out);
    if (n8 < n && n >= 8) weno5_transport2(scheme, f0, f1, local, D0, D1, n - 8, 8, eps, v0, v1, out);
    else if (n8 < n) weno5_transport2(scheme, f0, f1, local, D0, D1, n8, n - n8, eps, v0, v1, out);
}

#define TRANSPORT2_FLOWS(S, L)                                                                  \
    do {                                                                                        \
        if (v0 && v1) weno5_transport2_row(S, 1, 1, L, D0, D1, n, eps, v0, v1, out);             \
        else if (v0) weno5_transport2_row(S, 1, 0, L, D0, D1, n, eps, v0, v1, out);              \
        else weno5_transport2_row(S, 0, 1, L, D0, D1, n, eps, v0, v1, out);                      \
    } while (0)

HJ_LS_CLONES
int hj_ls_weno5_transport2_eps(int scheme, const double *const *D0, const double *const *D1, long n,
                               const double *eps, const double *v0, const double *v1, double *restrict out)
{
    if ((scheme != HJ_LS_WENO5A && scheme != HJ_LS_WENO5B) || (!v0 && !v1)) return 0;
    const int local = (!v0 || eps[0] < 0) && (!v1 || eps[1] < 0);
    if (scheme == HJ_LS_WENO5A && local) TRANSPORT2_FLOWS(HJ_LS_WENO5A, 1);
    else if (scheme == HJ_LS_WENO5A) TRANSPORT2_FLOWS(HJ_LS_WENO5A, 0);
    else if (local) TRANSPORT2_FLOWS(HJ_LS_WENO5B, 1);
    else TRANSPORT2_FLOWS(HJ_LS_WENO5B, 0);
    return 1;
}
#undef TRANSPORT2_FLOWS

double hj_ls_weno_eps_grid(const hj_ls_grid *g, const double *data, int d)
{
    /* rows along d: every interior node of the other dimensions */
    double m = 0;
    const ptrdiff_t s = g->stride[d];
    const double inv = 1.0 / g->dx[d];
    long idx[HJ_LS_MAXDIM] = {0};
    for (size_t q = 0; q < g->nodes / (size_t)g->N[d]; q++) {
        const double *p = data + hj_ls_index(g, idx);
        for (long i = -3; i < g->N[d] + 2; i++) {
            const double v = (p[(i + 1) * s] - p[i * s]) * inv;
            m = v * v > m ? v * v : m;
        }
        for (int e = 0; e < g->dim; e++) { /* next row: odometer over the dimensions other than d */
            if (e == d) continue;
            if (++idx[e] < g->N[e]) break;
            idx[e] = 0;
        }
    }
    return 1e-6 * m + 1e-99;
}

static int check_dim(const hj_ls_grid *g, int d, hj_error *err)
{
    if (d < 0 || d >= g->dim)
        return hj_error_set(err, HJ_EINVAL, "dimension mismatch: derivative in dimension %d of a %d-D grid", d, g->dim);
    return HJ_OK;
}

int hj_ls_upwind(const hj_ls_grid *g, int scheme, double *data, int d, double *dl, double *dr, hj_error *err)
{
    int rc = check_dim(g, d, err);
    if (rc) return rc;
    if (!hj_ls_scheme_name(scheme)) return hj_error_set(err, HJ_EINVAL, "unknown upwind scheme %d", scheme);
    hj_ls_fill_ghosts_width(g, data, hj_ls_scheme_ghost(scheme));
    const long n = g->N[0];
    int fail = 0, ws_fail = 0;
#ifdef _OPENMP
#pragma omp parallel reduction(| : fail)
#endif
    {
        double *w = malloc(sizeof(double) * HJ_LS_ROW_WORK * (size_t)n);
        if (!hj_sys_team_all(w != NULL, &ws_fail)) fail = 1;
        else {
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 32)
#endif
            for (size_t r = 0; r < g->rows; r++) {
                long i[HJ_LS_MAXDIM];
                const size_t k = hj_ls_row(g, r, i);
                hj_ls_upwind_row(scheme, data + k, g->stride[d], n, g->dx[d], dl + k, dr + k, w);
            }
        }
        free(w);
    }
    if (fail) return hj_error_set(err, HJ_ENOMEM, "out of memory for the derivative workspace");
    return HJ_OK;
}

int hj_ls_centered_first(const hj_ls_grid *g, double *data, int d, double *out, hj_error *err)
{
    int rc = check_dim(g, d, err);
    if (rc) return rc;
    hj_ls_fill_ghosts_width(g, data, 1); /* centered: one layer (corners included) */
    const ptrdiff_t s = g->stride[d];
    const double f = 0.5 / g->dx[d];
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, i);
        const double *p = data + k;
        double *o = out + k;
        for (long j = 0; j < g->N[0]; j++) o[j] = (p[j + s] - p[j - s]) * f;
    }
    return HJ_OK;
}

int hj_ls_hessian(const hj_ls_grid *g, double *data, int a, int b, double *out, hj_error *err)
{
    int rc = check_dim(g, a, err);
    if (!rc) rc = check_dim(g, b, err);
    if (rc) return rc;
    hj_ls_fill_ghosts_width(g, data, 1); /* centered: one layer (corners included) */
    const ptrdiff_t sa = g->stride[a], sb = g->stride[b];
    const double fa = 1 / (g->dx[a] * g->dx[a]), fab = 0.25 / (g->dx[a] * g->dx[b]);
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, i);
        const double *p = data + k;
        double *o = out + k;
        if (a == b)
            for (long j = 0; j < g->N[0]; j++) o[j] = (p[j + sa] - 2 * p[j] + p[j - sa]) * fa;
        else
            for (long j = 0; j < g->N[0]; j++)
                o[j] = (p[j + sa + sb] - p[j + sa - sb] - p[j - sa + sb] + p[j - sa - sb]) * fab;
    }
    return HJ_OK;
}

int hj_ls_laplacian(const hj_ls_grid *g, double *data, double *out, hj_error *err)
{
    (void)err;
    hj_ls_fill_ghosts_width(g, data, 1); /* centered: one layer (corners included) */
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, i);
        const double *p = data + k;
        double *o = out + k;
        for (long j = 0; j < g->N[0]; j++) o[j] = 0;
        for (int d = 0; d < g->dim; d++) {
            const ptrdiff_t s = g->stride[d];
            const double f = 1 / (g->dx[d] * g->dx[d]);
            for (long j = 0; j < g->N[0]; j++) o[j] += (p[j + s] - 2 * p[j] + p[j - s]) * f;
        }
    }
    return HJ_OK;
}

void hj_ls_curvature_at(const hj_ls_grid *g, const double *p, double *kappa, double *grad_mag)
{
    double c[HJ_LS_MAXDIM], c2 = 0, num = 0;
    for (int d = 0; d < g->dim; d++) {
        const ptrdiff_t s = g->stride[d];
        c[d] = (p[s] - p[-s]) * (0.5 / g->dx[d]);
        c2 += c[d] * c[d];
    }
    for (int a = 0; a < g->dim; a++) {
        const ptrdiff_t sa = g->stride[a];
        const double xx = (p[sa] - 2 * p[0] + p[-sa]) / (g->dx[a] * g->dx[a]);
        num += xx * (c2 - c[a] * c[a]);
        for (int b = 0; b < a; b++) {
            const ptrdiff_t sb = g->stride[b];
            const double xy = (p[sa + sb] - p[sa - sb] - p[-sa + sb] + p[-sa - sb]) * (0.25 / (g->dx[a] * g->dx[b]));
            num -= 2 * c[a] * c[b] * xy;
        }
    }
    const double mag = sqrt(c2);
    *kappa = mag > 0 ? num / (mag * mag * mag) : 0.0;
    if (grad_mag) *grad_mag = mag;
}

int hj_ls_curvature(const hj_ls_grid *g, double *data, double *kappa, double *grad_mag, hj_error *err)
{
    (void)err;
    hj_ls_fill_ghosts_width(g, data, 1); /* centered: one layer (corners included) */
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, i);
        for (long j = 0; j < g->N[0]; j++)
            hj_ls_curvature_at(g, data + k + j, kappa + k + j, grad_mag ? grad_mag + k + j : NULL);
    }
    return HJ_OK;
}

int hj_ls_gradient_norm(const hj_ls_grid *g, double *data, double *work, double *out, hj_error *err)
{
    long idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) out[k + (size_t)j] = 0;
    }
    for (int d = 0; d < g->dim; d++) {
        int rc = hj_ls_centered_first(g, data, d, work, err);
        if (rc) return rc;
        for (size_t r = 0; r < g->rows; r++) {
            const size_t k = hj_ls_row(g, r, idx);
            for (long j = 0; j < g->N[0]; j++) out[k + (size_t)j] += work[k + (size_t)j] * work[k + (size_t)j];
        }
    }
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) out[k + (size_t)j] = sqrt(out[k + (size_t)j]);
    }
    return HJ_OK;
}
