/* Unit tests of common/hj_ub, the UB-HJB scheme: one-dimensional fluxes,
 * the exact advection of Table 6, the band against the full grid on every
 * store, the errors of section 4 on the band and on the full grid. */
#include "hj_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hj_ub.h"
#include "hj_ub_dense.h"

static void flux_constant_and_step(void **state)
{
    (void)state;
    const double c[5] = {1, 1, 1, 1, 1}, mu[3] = {0.7, 0.7, 0.7};
    assert_true(hj_ub_update(c, mu) == 1);
    /* a step moving right by mu of a cell: the first -1 cell gets 2 mu - 1 */
    const double w[5] = {1, 1, -1, -1, -1};
    assert_close(hj_ub_update(w, mu), 2 * 0.7 - 1, 1e-15, 0);
    const double w2[5] = {1, 1, 1, -1, -1};
    assert_true(hj_ub_update(w2, mu) == 1);
    /* the same to the left */
    const double wl[5] = {-1, -1, -1, 1, 1}, mul[3] = {-0.4, -0.4, -0.4};
    assert_close(hj_ub_update(wl, mul), 2 * 0.4 - 1, 1e-15, 0);
    /* anti-diffusion: a fractional cell behind a sharp front empties first */
    const double w3[5] = {1, 1, 0, -1, -1}, mu3[3] = {0.5, 0.5, 0.5};
    assert_close(hj_ub_update(w3, mu3), 1, 1e-15, 0);
    /* a pulse narrower than a cell (covered fraction a) is spread, not
     * moved: a (1 - c) stays, a c goes to the next cell
     * (paper3_ultrabee/overview.md, Table 13's excess past the cap) */
    const double a = 0.3, mup[3] = {0.7, 0.7, 0.7};
    const double pj[5] = {1, 1, 1 - 2 * a, 1, 1}, pj1[5] = {1, 1 - 2 * a, 1, 1, 1};
    assert_close(hj_ub_update(pj, mup), 1 - 2 * a * (1 - 0.7), 1e-15, 0);
    assert_close(hj_ub_update(pj1, mup), 1 - 2 * a * 0.7, 1e-15, 0);
}

/* ---- 2-D and 3-D test problems --------------------------------------------- */

typedef struct {
    double lo[HJ_BAND_DMAX], hi[HJ_BAND_DMAX]; /* the target box */
    double vel[HJ_BAND_DMAX];
    int kind; /* 0 constant, 1 rotation, 2 rendez-vous (1, a), a = +-1; 3 constant, box through the
                 grid's edge x1 = -2, flow entering there (the boundary value 1 flows in) */
    double t; /* time of the exact solution */
} box_case;

static void dyn(double t, const double *x, int a, double *f, void *vctx)
{
    (void)t;
    const box_case *c = vctx;
    if (c->kind == 0 || c->kind == 3) { f[0] = c->vel[0]; f[1] = c->vel[1]; f[2] = c->vel[2]; }
    else if (c->kind == 1) { f[0] = -x[1]; f[1] = x[0]; f[2] = 0.3; }
    else { f[0] = 1; f[1] = a ? 1 : -1; f[2] = a ? -0.5 : 0.5; }
}

static double avg_box(const double *blo, const double *bhi, void *vctx)
{
    const box_case *c = vctx;
    return hj_ub_avg_box(2 + (c->hi[2] > c->lo[2]), blo, bhi, c->lo, c->hi);
}

/* exact for the constant advection in 2-D */
static int inside_moved(const double *x, void *vctx)
{
    const box_case *c = vctx;
    for (int k = 0; k < 2; k++) {
        const double y = x[k] - c->vel[k] * c->t;
        if (y < c->lo[k] || y > c->hi[k]) return 0;
    }
    return 1;
}

static hj_ub_problem square_problem(box_case *c, int n)
{
    hj_ub_problem pb = {
        .d = 2, .n = n, .lo = {-2, -2}, .hi = {2, 2}, .ncontrols = 1, .dyn = dyn, .cfl = 0.9, .boundary = 1,
        .avg0 = avg_box, .ctx = c,
    };
    memcpy(pb.bbox_lo, c->lo, sizeof pb.bbox_lo);
    memcpy(pb.bbox_hi, c->hi, sizeof pb.bbox_hi);
    return pb;
}

/* Table 6: f = (-2, -1), T = 1.  The scheme moves the cell averages
 * exactly: every value equals the average (7b) of the moved square.  At
 * N = 50 the signs then match the exact ones everywhere (L1 error 0); at
 * N = 100, 200 one corner cell has its centre inside but less than half of
 * it covered (0.625^2), so its sign differs whatever the scheme. */
static void exact_advection_table6(void **state)
{
    (void)state;
    const int sizes[] = {50, 100, 200};
    for (int s = 0; s < 3; s++) {
        box_case c = {{0.5, -0.5, 0}, {1.5, 0.5, 0}, {-2, -1, 0}, 0, 0};
        hj_ub_problem pb = square_problem(&c, sizes[s]);
        hj_ub_solver sv;
        hj_error err;
        assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), HJ_OK);
        assert_int_equal(hj_ub_run(&sv, 1.0, &err), HJ_OK);
        assert_true(sv.t == 1.0);
        const double moved_lo[2] = {-1.5, -1.5}, moved_hi[2] = {-0.5, -0.5};
        for (int i = 0; i < pb.n; i++)
            for (int j = 0; j < pb.n; j++) {
                int idx[2] = {i, j};
                double x[2], blo[2], bhi[2];
                hj_ub_centre(&sv, idx, x);
                for (int k = 0; k < 2; k++) { blo[k] = x[k] - sv.dx[k] / 2; bhi[k] = x[k] + sv.dx[k] / 2; }
                const double *p = hj_band_find(sv.s, idx), exact = hj_ub_avg_box(2, blo, bhi, moved_lo, moved_hi);
                if (p) assert_close(*p, exact, 1e-12, 0);
                else assert_true(exact == 1 || exact == -1);
            }
        c.t = 1.0;
        double l1, haus;
        assert_int_equal(hj_ub_errors(&sv, inside_moved, &c, &l1, &haus, &err), HJ_OK);
        if (s == 0) assert_true(l1 == 0);
        else assert_close(l1, sv.dx[0] * sv.dx[1], 1e-15, 1e-12);
        assert_true(haus <= 1.1 * sv.dx[0]);
        hj_ub_free(&sv);
    }
}

/* The band (every sparse store) gives the same values as the full grid. */
static void band_equals_full_grid(void **state)
{
    (void)state;
    for (int d = 2; d <= 3; d++)
        for (int kind = 0; kind < 4; kind++) {
            box_case c = {{0.3, -0.5, -0.4}, {1.1, 0.5, 0.2}, {-1.3, 0.7, 0.4}, kind, 0};
            if (kind == 3) c = (box_case){{-3, -0.5, -0.4}, {0.1, 0.5, 0.2}, {0.9, 0.3, 0.2}, kind, 0};
            if (d == 2) c.lo[2] = c.hi[2] = 0;
            hj_ub_problem pb = square_problem(&c, d == 2 ? 41 : 17);
            pb.d = d;
            pb.lo[2] = -2;
            pb.hi[2] = 2;
            pb.ncontrols = kind == 2 ? 2 : 1;
            pb.target = kind == 1;
            pb.dtmax = 0.02; /* the same steps on the band and on the full grid */
            hj_ub_solver full;
            assert_int_equal(hj_ub_init(&full, &pb, HJ_BAND_FS, NULL), HJ_OK);
            for (int st = 0; st < 12; st++) assert_int_equal(hj_ub_step(&full, 0.8, NULL), HJ_OK);
            for (int sk = HJ_BAND_FLS; sk < HJ_BAND_NKINDS; sk++) {
                hj_ub_solver band;
                assert_int_equal(hj_ub_init(&band, &pb, sk, NULL), HJ_OK);
                for (int st = 0; st < 12; st++) assert_int_equal(hj_ub_step(&band, 0.8, NULL), HJ_OK);
                assert_true(band.t == full.t);
                assert_true(hj_band_count(band.s) < hj_band_count(full.s));
                int idx[HJ_BAND_DMAX] = {0};
                int64_t total = 1;
                for (int k = 0; k < d; k++) total *= pb.n;
                for (int64_t l = 0; l < total; l++) {
                    int64_t r = l;
                    for (int k = d - 1; k >= 0; k--) { idx[k] = (int)(r % pb.n); r /= pb.n; }
                    const double vf = *hj_band_find(full.s, idx);
                    const double *vb = hj_band_find(band.s, idx);
                    if (vb) assert_close(*vb, vf, 1e-13, 0);
                    else assert_true(vf == 1 || vf == -1);
                }
                hj_ub_free(&band);
            }
            hj_ub_free(&full);
        }
}

static double avg_left(const double *blo, const double *bhi, void *vctx)
{
    (void)vctx;
    const double lo[2] = {-10, -10}, hi[2] = {0.13, 10};
    return hj_ub_avg_box(2, blo, bhi, lo, hi);
}

static int inside_left(const double *x, void *vctx)
{
    (void)vctx;
    return x[0] <= 0.13;
}

/* Lines (along x2) entirely inside the set store no node: their values
 * come from the neighbouring lines; the L1 error of the data is 0.  (The
 * edge is off the nodes: a node on the edge would be a tie.) */
static void errors_recover_unstored_lines(void **state)
{
    (void)state;
    box_case c = {{0}, {0}, {0, 0, 0}, 0, 0};
    hj_ub_problem pb = square_problem(&c, 41);
    pb.avg0 = avg_left;
    pb.boundary = -1; /* else the -1 cells on the grid's edge are stored (they border the boundary value) */
    pb.bbox_lo[0] = pb.bbox_lo[1] = -2;
    pb.bbox_hi[0] = 0.13;
    pb.bbox_hi[1] = 2;
    hj_ub_solver sv;
    assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, NULL), HJ_OK);
    /* the lines inside the set (x < 0.13 less a cell and a half) store no
     * node; the +1 cells on the grid's edge do (they border the boundary
     * value) */
    int lines_empty = 0;
    for (int i = 0; i < 41; i++) {
        if (-2 + (i + 1.5) * sv.dx[0] >= 0.13) break;
        double *p[41];
        hj_band_find_run(sv.s, (int[]){i, 0}, 41, p);
        int none = 1;
        for (int j = 0; j < 41; j++) none &= p[j] == NULL;
        lines_empty += none;
    }
    assert_int_equal(lines_empty, 20);
    double l1, haus;
    assert_int_equal(hj_ub_errors(&sv, inside_left, NULL, &l1, &haus, NULL), HJ_OK);
    assert_true(l1 == 0);
    assert_close(haus, 0.03, 1e-6 * sv.dx[0], 0); /* centres at x = 0.1, front at 0.13; bisection to 1e-6 dx */
    hj_ub_free(&sv);
}

static void averages(void **state)
{
    (void)state;
    const double blo[2] = {0, 0}, bhi[2] = {1, 1}, clo[2] = {0.5, -1}, chi[2] = {3, 0.25};
    assert_close(hj_ub_avg_box(2, blo, bhi, clo, chi), 1 - 2 * 0.125, 1e-15, 0);
    const double c[3] = {0, 0, 0}, lo3[3] = {-1, -1, -1}, hi3[3] = {1, 1, 1};
    assert_close(hj_ub_avg_ball(3, lo3, hi3, c, 0.5, 4), 0.75, 1e-15, 0); /* 8 of 64 samples inside */
    assert_true(hj_ub_avg_ball(3, lo3, hi3, c, 2, 4) == -1);  /* the box inside the ball */
    const double far[3] = {5, 0, 0};
    assert_true(hj_ub_avg_ball(3, lo3, hi3, far, 1, 4) == 1);
}

/* hj_front_grid_errors on the values of a full store gives the errors of
 * hj_ub_errors (the level set runs are measured as UB is), in 2-D and
 * 3-D (lines of lines: the signs of the lower lines come from a ring), with
 * the exact front sampled on the centre lines and on lines refined 4 times. */
typedef struct {
    hj_ub_solver *sv;
} field_ctx;

static double field_value(const int *idx, void *vctx)
{
    field_ctx *f = vctx;
    const double *p = hj_band_find(f->sv->s, idx);
    return p ? *p : NAN;
}

static void field_errors_equal_solver_errors(void **state)
{
    (void)state;
    for (int d = 2; d <= 3; d++)
      for (int sub = 1; sub <= 4; sub += 3) {
        box_case c = {{0.5, -0.5, -0.4}, {1.5, 0.5, d == 3 ? 0.4 : -0.4}, {-2, -1, 0}, 1, 0};
        hj_ub_problem pb = square_problem(&c, d == 3 ? 21 : 41);
        pb.d = d;
        pb.front_sub = sub;
        pb.lo[2] = -2;
        pb.hi[2] = 2;
        hj_ub_solver sv;
        assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_FS, NULL), HJ_OK);
        assert_int_equal(hj_ub_run(&sv, 0.4, NULL), HJ_OK);
        c.t = 0.4;
        double l1, haus, l1f, hausf;
        int64_t cells = -1;
        assert_int_equal(hj_ub_errors(&sv, inside_moved, &c, &l1, &haus, NULL), HJ_OK);
        field_ctx fc = {&sv};
        assert_int_equal(hj_front_grid_errors(d, pb.n, pb.lo, sv.dx, field_value, &fc, inside_moved, &c, pb.front_sub, &l1f,
                                         &hausf, &cells, NULL),
                         HJ_OK);
        assert_true(l1 > 0 && haus > 0 && cells > 0);
        assert_true(l1f == l1);
        assert_true(hausf == haus);
        hj_ub_free(&sv);
    }
}

/* Dynamics that give NaN or infinity: HJ_ENONFINITE naming the node (a
 * NaN dropped out of the CFL rate and the run went on; an infinity gave
 * dt = 0, and hj_ub_run never ended); a NaN or infinite final time is
 * HJ_EINVAL (NaN used to return HJ_OK at once). */
static void nonfinite_dynamics_and_times(void **state)
{
    (void)state;
    const double bad[2] = {NAN, INFINITY};
    for (int b = 0; b < 2; b++) {
        box_case c = {.lo = {-0.5, -0.5}, .hi = {0.5, 0.5}, .vel = {bad[b], 0.5, 0}, .kind = 0};
        hj_ub_problem pb = square_problem(&c, 41);
        hj_ub_solver sv;
        hj_error err = {0};
        assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), HJ_OK);
        assert_int_equal(hj_ub_step(&sv, 0.5, &err), HJ_ENONFINITE);
        assert_non_null(strstr(err.msg, "f_0"));
        assert_non_null(strstr(err.msg, "control 0"));
        assert_true(sv.t == 0);
        hj_ub_free(&sv);
    }
    box_case c = {.lo = {-0.5, -0.5}, .hi = {0.5, 0.5}, .vel = {1, 0.5, 0}, .kind = 0};
    hj_ub_problem pb = square_problem(&c, 41);
    hj_ub_solver sv;
    hj_error err = {0};
    assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), HJ_OK);
    assert_int_equal(hj_ub_run(&sv, NAN, &err), HJ_EINVAL);
    assert_int_equal(hj_ub_step(&sv, NAN, &err), HJ_EINVAL);
    assert_int_equal(hj_ub_run(&sv, INFINITY, &err), HJ_EINVAL);
    assert_int_equal(hj_ub_run(&sv, 0.25, &err), HJ_OK);
    assert_true(sv.t == 0.25);
    hj_ub_free(&sv);
}

/* Parameters no run can use are refused by both solvers: a NaN boundary
 * value made NaN values, a NaN or negative snap and a NaN dtmax were
 * taken as their defaults, a NaN bounding box was converted to int. */
static void bad_parameters(void **state)
{
    (void)state;
    box_case c = {.lo = {-0.5, -0.5}, .hi = {0.5, 0.5}, .vel = {1, 0.5, 0}, .kind = 0};
    for (int k = 0; k < 7; k++) {
        hj_ub_problem pb = square_problem(&c, 41);
        switch (k) {
        case 0: pb.boundary = NAN; break;
        case 1: pb.snap = NAN; break;
        case 2: pb.snap = -1e-3; break;
        case 3: pb.snap = 1; break;
        case 4: pb.dtmax = NAN; break;
        case 5: pb.hi[1] = INFINITY; break;
        default: pb.bbox_lo[0] = NAN; break;
        }
        hj_ub_solver sv;
        hj_error err = {0};
        assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), HJ_EINVAL);
        hj_ub_free(&sv);
        if (k == 6) continue; /* the full grid has no bounding box */
        hj_ub_dense ws;
        assert_int_equal(hj_ub_dense_init(&ws, &pb, NULL, &err), HJ_EINVAL);
        hj_ub_dense_free(&ws);
    }
}

/* A bounding box far beyond the domain (finite) is clamped to the grid
 * before the conversion to int, which overflowed (undefined behaviour:
 * caught by the sanitizer build): the box over the whole domain starts,
 * and so does a box wholly outside it around a set outside it too.  A box
 * wholly outside the domain around a set inside it started an empty band
 * and the run went on with the set lost; it is refused, by name. */
static void huge_bounding_box(void **state)
{
    (void)state;
    for (int k = 0; k < 3; k++) {
        box_case c = {.lo = {-0.5, -0.5}, .hi = {0.5, 0.5}, .vel = {1, 0.5, 0}, .kind = 0};
        if (k == 2) c.lo[0] = 1.5e10, c.hi[0] = 1.6e10; /* the set outside the domain too */
        hj_ub_problem pb = square_problem(&c, 41);
        for (int d = 0; d < 2; d++) pb.bbox_lo[d] = k ? 1e10 : -1e10, pb.bbox_hi[d] = k ? 2e10 : 1e10;
        hj_ub_solver sv;
        hj_error err = {0};
        assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), k == 1 ? HJ_EINVAL : HJ_OK);
        if (k == 1) assert_non_null(strstr(err.msg, "lies outside the domain"));
        else assert_int_equal(hj_band_count(sv.s), k ? 0 : 120);
        hj_ub_free(&sv);
    }
}

/* The scan of hj_ub_init inserted each cell of D^0 by hj_band_insert,
 * which searches a list line of SSD or CRS from its head: a face of the
 * set lying along a line (m band cells on one list) cost O(m^2), 1.6 s at
 * n = 1e5 on a face of 2e4 cells, several minutes here (faces of 3e5
 * cells).  The scan goes in lexicographic order, so the cells are
 * appended (O(1) each): well under a second here (about 20 s under
 * valgrind).  The alarm stops the test where it would hang. */
static void init_linear_in_the_band(void **state)
{
    (void)state;
    box_case c = {.lo = {-0.6, -0.6}, .hi = {0.6, 0.6}, .vel = {1, 0.5, 0}, .kind = 0};
    hj_ub_problem pb = square_problem(&c, 1000000);
    hj_ub_solver sv;
    hj_error err = {0};
    alarm(120);
    assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), HJ_OK);
    alarm(0);
    /* the square's 4 faces, each 3 cells by 3e5 */
    assert_true(hj_band_count(sv.s) > 3500000 && hj_band_count(sv.s) < 3700000);
    hj_ub_free(&sv);
}

/* The step inserted the new band nodes and removed the old ones by the
 * search from each list line's head: a face of the set along a line of m
 * cells cost O(m^2) per step once the face moved across lines (1.7 s per
 * step at n = 1e5 with faces of 2e4 cells, 94 % in the list search; a few
 * minutes here, faces of 2e5 cells).  The inserts and removals now search
 * from the cell last looked up (hj_band_insert_near, _remove_near), the
 * same store: a fraction of a second here.  The alarm stops the test
 * where it would hang. */
static void step_linear_in_the_band(void **state)
{
    (void)state;
    /* a strip along the last index, moved across the lines */
    box_case c = {.lo = {-0.05, -1.9}, .hi = {0.05, 1.9}, .vel = {1, 0, 0}, .kind = 0};
    hj_ub_problem pb = square_problem(&c, 200000);
    hj_ub_solver sv;
    hj_error err = {0};
    alarm(120);
    assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), HJ_OK);
    const size_t n0 = hj_band_count(sv.s);
    assert_int_equal(hj_ub_step(&sv, 1, &err), HJ_OK);
    alarm(0);
    assert_true(n0 > 1000000 && hj_band_count(sv.s) > n0); /* the long faces, 3 cells by 1.9e5 */
    hj_ub_free(&sv);
}

/* boundary = -1: outside the domain is inside the set, which flows in
 * through the edges the flow enters by.  The +1 cells on the domain's
 * edge differ from their outside neighbour, so they belong to D^0, but
 * the scan of the bounding box never saw them: every store but FS
 * stopped at the first step ("band invariant violated").  Now every store
 * gives FS's values, bit for bit (a constant flow: the same steps). */
static void boundary_inside_the_set(void **state)
{
    (void)state;
    box_case c = {.lo = {-0.5, -0.3}, .hi = {0.2, 0.4}, .vel = {1, 0.5, 0}, .kind = 0};
    const int n = 41;
    double *ref = malloc((size_t)n * n * sizeof *ref), *v = malloc((size_t)n * n * sizeof *v);
    for (int kind = HJ_BAND_FS; kind < HJ_BAND_NKINDS; kind++) {
        hj_ub_problem pb = square_problem(&c, n);
        pb.boundary = -1;
        hj_ub_solver sv;
        hj_error err = {0};
        assert_int_equal(hj_ub_init(&sv, &pb, (hj_band_kind)kind, &err), HJ_OK);
        assert_int_equal(hj_ub_run(&sv, 0.7, &err), HJ_OK);
        assert_int_equal(hj_ub_values(&sv, kind ? v : ref, &err), HJ_OK);
        if (kind) assert_memory_equal(v, ref, (size_t)n * n * sizeof *v);
        hj_ub_free(&sv);
    }
    /* the strips that came in: x < -2 + 0.7 and y < -2 + 0.35 */
    assert_true(ref[0] == -1 && ref[(size_t)5 * n + 20] == -1 && ref[(size_t)20 * n + 2] == -1);
    assert_true(ref[(size_t)20 * n + 40] == 1 && ref[(size_t)40 * n + 40] == 1);
    free(ref);
    free(v);
}

/* A bounding box that does not hold Omega_0 cut the set without a word:
 * one left at zero (a point at the origin, inside the square) stored no
 * band node, so the run went on with an empty set; an inverted box was
 * taken as well.  Both are refused, each with a message naming the box;
 * so are a missing avg0 and an out-of-range cfl, each by name. */
static void bounding_box_must_hold_the_set(void **state)
{
    (void)state;
    box_case c = {.lo = {-0.5, -0.5}, .hi = {0.5, 0.5}, .vel = {1, 0.5, 0}, .kind = 0};
    for (int k = 0; k < 5; k++) {
        hj_ub_problem pb = square_problem(&c, 41);
        const char *want = "bounding box";
        switch (k) {
        case 0: memset(pb.bbox_lo, 0, sizeof pb.bbox_lo), memset(pb.bbox_hi, 0, sizeof pb.bbox_hi); break;
        case 1: pb.bbox_hi[1] = 0.1; break;                    /* cuts the square's top */
        case 2: pb.bbox_lo[0] = 0.6, pb.bbox_hi[0] = -0.6; break; /* inverted */
        case 3: pb.avg0 = NULL, want = "avg0"; break;
        default: pb.cfl = 1.5, want = "cfl"; break;
        }
        hj_ub_solver sv;
        hj_error err = {0};
        assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err), HJ_EINVAL);
        assert_non_null(strstr(err.msg, want));
        hj_ub_free(&sv);
    }
}

/* A refusal of hj_ub_init after the store was made (here the bounding box
 * wholly outside the domain around a set inside it) kept the store: a
 * caller that took the error for "nothing to free" leaked it.  Now sv is
 * left empty, as hj_ub_free leaves it. */
static void refused_init_keeps_nothing(void **state)
{
    (void)state;
    box_case c = {.lo = {-0.5, -0.5}, .hi = {0.5, 0.5}, .vel = {1, 0.5, 0}, .kind = 0};
    hj_ub_problem pb = square_problem(&c, 41);
    for (int d = 0; d < 2; d++) pb.bbox_lo[d] = 1e10, pb.bbox_hi[d] = 2e10;
    for (int kind = HJ_BAND_FS; kind < HJ_BAND_NKINDS; kind++) {
        hj_ub_solver sv;
        hj_error err = {0};
        assert_int_equal(hj_ub_init(&sv, &pb, (hj_band_kind)kind, &err), HJ_EINVAL);
        assert_null(sv.s);
        hj_ub_free(&sv); /* harmless */
    }
}

HJ_TEST_MAIN("hj_ub", NULL, NULL, cmocka_unit_test(bad_parameters), cmocka_unit_test(huge_bounding_box),
             cmocka_unit_test(init_linear_in_the_band), cmocka_unit_test(step_linear_in_the_band),
             cmocka_unit_test(boundary_inside_the_set), cmocka_unit_test(refused_init_keeps_nothing),
             cmocka_unit_test(bounding_box_must_hold_the_set), cmocka_unit_test(flux_constant_and_step), cmocka_unit_test(exact_advection_table6),
             cmocka_unit_test(band_equals_full_grid), cmocka_unit_test(errors_recover_unstored_lines),
             cmocka_unit_test(averages), cmocka_unit_test(field_errors_equal_solver_errors),
             cmocka_unit_test(nonfinite_dynamics_and_times))
