/* The exact front heights of tripleSine's check (published/triple_sine.tsv,
 * "not published": our own reference values), recomputed here so that a
 * reviewer can audit them.  For b = 0 the front moves with unit normal
 * speed; by Huygens' principle the front above x0 at time t is at
 *     y(x0, t) = max over |s - x0| <= t of f(s) + sqrt(t^2 - (s - x0)^2),
 * f(s) = 0.75 - 0.5 sin(3 pi (s + 0.5)) the initial front.  The maximum is
 * found by a fine search and refined by golden section. */
#include "hj_test.h"
#include "hj_math.h"


static double front0(double s) { return 0.75 - 0.5 * sin(3 * HJ_PI * (s + 0.5)); }

static double reach(double s, double x0, double t) { return front0(s) + sqrt(fmax(t * t - (s - x0) * (s - x0), 0)); }

static double huygens_height(double x0, double t)
{
    const int m = 100000;
    int best = 0;
    double vbest = -INFINITY;
    for (int i = 0; i <= m; i++) {
        const double v = reach(x0 - t + 2 * t * i / m, x0, t);
        if (v > vbest) vbest = v, best = i;
    }
    double a = x0 - t + 2 * t * (best > 0 ? best - 1 : 0) / m, b = x0 - t + 2 * t * (best < m ? best + 1 : m) / m;
    const double g = 0.5 * (sqrt(5.0) - 1);
    for (int it = 0; it < 100; it++) {
        const double p = b - g * (b - a), q = a + g * (b - a);
        if (reach(p, x0, t) > reach(q, x0, t)) b = q; else a = p;
    }
    const double v = reach(0.5 * (a + b), x0, t);
    return v > vbest ? v : vbest;
}

static void reference_heights(void **state)
{
    (void)state;
    /* the values of published/triple_sine.tsv, 7 digits */
    assert_close(huygens_height(0.2, 0.5), 1.710286, 6e-7, 0);
    assert_close(huygens_height(1.0, 0.5), 1.630852, 6e-7, 0);
    /* the crest: the arc grown from the maximum, 1.25 + t */
    assert_close(huygens_height(0.0, 0.5), 1.75, 1e-12, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(reference_heights)};
    return cmocka_run_group_tests_name("huygens", tests, NULL, NULL);
}
