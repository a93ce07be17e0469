#!/usr/bin/env bash
# studies.sh -- the data of the studies of paper 1 shown in the report, one
# TSV per study on stdout (a header row, '#' comment lines); the prose and
# tables that present them are notes/<study>.md, filled by report/note.awk.
#
#   studies.sh eps-scan BINDIR PUBLISHED3   Example 2, Lax-Wendroff: L1 error
#       for several WENO eps = C h^2.  Near the centre of case (b) (f = 0)
#       the discrete problem has several fixed points; this shows how the
#       one reached depends on eps (the reason given for Table 3.3 (b)).
#   studies.sh richardson-box BINDIR PUBLISHED2   Example 2, Richardson: the
#       paper's small box [-2h, 2h]^2 around each node, widened by one node
#       of each grid (default) or not, against one box per edge (exact for
#       case (a)), L1 errors and iterations beside the paper's.
#   studies.sh exclude BINDIR PUBLISHED4 PUBLISHED5 RESULTS   Examples 3 and
#       4: the errors measured outside the paper's boxes around the singular
#       centres, or with the nodes closer than 0.15 to a centre left out
#       (default: the reproduction's own tables in RESULTS).
#   studies.sh guess BINDIR PUBLISHED2 PUBLISHED3   Example 2: the initial
#       guess from first order sweeps on the boundary condition alone
#       (default) against sweeps that also hold the Category III values;
#       errors and iterations of Tables 3.2 and 3.3.
#   studies.sh roundoff BINDIR PUBLISHED2 PUBLISHED3 RESULTS   Example 2 (b):
#       the initial guess perturbed by relative noise of round-off size and
#       larger (fixed seeds); which fixed point near the centre the
#       iteration reaches, Table 3.3 (b) at N = 80 ... 640 and Table 3.2 (b)
#       at 640 (R = 0: the reproduction's own tables in RESULTS), and over
#       16 seeds at N = 320 how often the exact solution is reached.
#   studies.sh treatments BINDIR           Category III treatments compared:
#       first order values (refs. [7,16]) against the paper's Richardson and
#       Lax-Wendroff values, Examples 1 and 2, L1 errors and fitted order.
#
# Words the data carries for the notes:
#   verdict      ours against the published value as common/hj_compare.h
#                rates an error: match within 5 % (or both <= 1e-10, the
#                round-off level), close within a factor 2, else differs;
#                "-" where either value is missing.  In eps-scan, case (a)
#                has no round-off level: its small errors are what eps
#                leaves at the kinks of its solution (they grow as C^2)
#   fixed_point  Example 2 (b): exact when L1 < 1e-10 (the exact solution
#                up to the stopping threshold delta), other otherwise
set -euo pipefail
what=$1 bin=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The published sizes of every study.
sizes="80 160 320 640"

# awk functions shared by the studies (see "Words" above).
lib='
function isnum(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
function abs(x) { return x < 0 ? -x : x }
function verdict(p, c, no_floor,   r) {
    if (!isnum(p) || !isnum(c)) return "-"
    p += 0; c += 0
    if (!no_floor && abs(p) <= 1e-10 && abs(c) <= 1e-10) return "match"
    if (p == c) return "match"
    if (p != 0 && abs(c / p - 1) <= 0.05 + 1e-12) return "match"
    if (p == 0 || c == 0 || (p < 0) != (c < 0)) return "differs"
    r = c / p; if (r < 1) r = 1 / r
    return r <= 2 + 1e-12 ? "close" : "differs"
}
function fixed_point(e) { return isnum(e) ? (e + 0 < 1e-10 ? "exact" : "other") : "-" }
function ratio(a, b) { return isnum(a) && isnum(b) && b + 0 != 0 ? sprintf("%.17g", a / b) : "-" }
# Columns of a table file by name: col[NAME] = index, from its header row.
function header(   i) { delete col; for (i = 1; i <= NF; i++) col[$i] = i }
'

case $what in
eps-scan)
    pub=$3
    printf '# eps-scan: Example 2, Lax-Wendroff treatment, WENO eps = C h^2; L1 error of Table 3.3 beside the published one (%s)\n' "$pub"
    printf '# fixed_point: case (b) only; b_matches: how many case (b) rows of this C have verdict match\n'
    printf 'C\tcase\tN\tL1\tpaper_L1\tverdict\tfixed_point\tb_matches\n'
    for C in 1e-4 7e-5 5e-5 3e-5 2e-5 1e-5 1e-6 1e-7; do
        "$bin/example2" --strategy lax-wendroff --eps-h2 "$C" --out-dir "$tmp/$C" > /dev/null
        awk -F'\t' -v C="$C" "$lib"'
            FNR == 1 { file++; hdr = 0 } /^#/ { next }
            !hdr++ { header(); next }
            file == 1 { paper[$1, $2] = $col["L1"]; next }
            { n++; k[n] = $1; N[n] = $2; e[n] = $col["L1"]; v[n] = verdict(paper[$1, $2], e[n], $1 == "a")
              if ($1 == "b" && v[n] == "match") matches++ }
            END { for (i = 1; i <= n; i++)
                      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%d\n", C, k[i], N[i], e[i], paper[k[i], N[i]], v[i],
                             k[i] == "b" ? fixed_point(e[i]) : "-", matches }' "$pub" "$tmp/$C/table3.3.tsv"
    done
    ;;
richardson-box)
    pub=$3
    printf '# richardson-box: Example 2, Richardson treatment, the boxes of the local first order sweeps (--richardson-box); Table 3.2 beside the published values (%s)\n' "$pub"
    printf '# b_over_a: L1 of case (b) over case (a) at the same N (case (b) rows)\n'
    printf 'boxes\tcase\tN\tL1\titer\tpaper_L1\tpaper_iter\tverdict\tb_over_a\tpaper_b_over_a\n'
    for b in node tight piece; do
        "$bin/example2" --strategy richardson --richardson-box $b --out-dir "$tmp/$b" > /dev/null
        awk -F'\t' -v boxes=$b "$lib"'
            FNR == 1 { file++; hdr = 0 } /^#/ { next }
            !hdr++ { header(); next }
            file == 1 { pe[$1, $2] = $col["L1"]; pi[$1, $2] = $col["iter"]; next }
            { n++; k[n] = $1; N[n] = $2; e[n] = $col["L1"]; it[n] = $col["iter"]; ours[$1, $2] = e[n] }
            END { for (i = 1; i <= n; i++) {
                      p = pe[k[i], N[i]]
                      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", boxes, k[i], N[i], e[i], it[i], p,
                             pi[k[i], N[i]], verdict(p, e[i]), k[i] == "b" ? ratio(e[i], ours["a", N[i]]) : "-",
                             k[i] == "b" ? ratio(p, pe["a", N[i]]) : "-" } }' "$pub" "$tmp/$b/table3.2.tsv"
    done
    ;;
exclude)
    pub4=$3 pub5=$4 res=$5
    printf '# exclude: Examples 3 and 4, errors measured without the nodes at distance < 0.15 from a singular centre (distance: the reproduction in %s) or outside the paper'"'"'s closed boxes (literal), beside the published values (%s, %s)\n' "$res" "$pub4" "$pub5"
    printf '# value "-": that N is not in the results; ratio: value over paper; diff_pct: 100 |ratio - 1|\n'
    printf 'table\terror\tmeasured\tN\tvalue\tpaper\tratio\tdiff_pct\n'
    for e in 3 4; do
        t=table3.$((e + 1)) pub=$pub4
        [ $e = 4 ] && pub=$pub5
        "$bin/example$e" --exclude literal --out-dir "$tmp/x$e" > /dev/null
        for q in L1 Linf; do
            for m in distance literal; do
                f=$res/$t.tsv
                [ $m = literal ] && f=$tmp/x$e/$t.tsv
                awk -F'\t' -v t="${t#table}" -v q=$q -v m=$m -v sizes="$sizes" "$lib"'
                    FNR == 1 { file++; hdr = 0 } /^#/ { next }
                    !hdr++ { header(); next }
                    file == 1 { p[$2] = $col[q]; next }
                    $1 == "-" { v[$2] = $col[q] }
                    END { n = split(sizes, N, " ")
                          for (i = 1; i <= n; i++) {
                              c = (N[i] in v) ? v[N[i]] : "-"; r = ratio(c, p[N[i]])
                              printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", t, q, m, N[i], c, p[N[i]], r,
                                     r == "-" ? "-" : sprintf("%.17g", 100 * abs(r - 1)) } }' "$pub" "$f"
            done
        done
    done
    ;;
guess)
    pub2=$3 pub3=$4
    printf '# guess: Example 2 started from first order sweeps on the boundary condition alone (physical) or also holding the Category III values (category-iii); Tables 3.2 (richardson) and 3.3 (lax-wendroff) beside the published values (%s, %s)\n' "$pub2" "$pub3"
    printf '# "-": not in the published table\n'
    printf 'strategy\tguess\tcase\tN\tL1\tLinf\titer\tpaper_L1\tpaper_Linf\tpaper_iter\n'
    for s in lax-wendroff richardson; do
        t=table3.3 pub=$pub3
        [ $s = richardson ] && t=table3.2 pub=$pub2
        for g in physical category-iii; do
            "$bin/example2" --strategy $s --guess $g --out-dir "$tmp/$s$g" > /dev/null
            awk -F'\t' -v s=$s -v g=$g "$lib"'
                function cell(name) { return (name in col) ? $col[name] : "-" }
                FNR == 1 { file++; hdr = 0 } /^#/ { next }
                !hdr++ { header(); next }
                file == 1 { p[$1, $2] = cell("L1") "\t" cell("Linf") "\t" cell("iter"); next }
                { printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", s, g, $1, $2, $col["L1"], $col["Linf"], $col["iter"], p[$1, $2] }' \
                "$pub" "$tmp/$s$g/$t.tsv"
        done
    done
    ;;
roundoff)
    pub2=$3 pub3=$4 res=$5
    printf '# roundoff: Example 2 (b), every Category IV value of the initial guess multiplied by 1 + R u, u uniform in [-1, 1) (--guess-noise R --seed S); case (b) of Table 3.3 (Lax-Wendroff) and of Table 3.2 (Richardson) beside the published values (%s, %s)\n' "$pub3" "$pub2"
    printf '# runs: sizes (R = 0 is the reproduction in %s; N = 80 ... 640, Table 3.2 at 640 only) or seeds (Table 3.3 at N = 320, seeds 1-16)\n' "$res"
    printf '# L1 "-": that N is not in the results; vs_unperturbed: L1 and iterations equal to the R = 0 row (same) or not (changed)\n'
    printf 'runs\tR\tseed\ttable\tN\tL1\titer\tfixed_point\tpaper_L1\tpaper_iter\tvs_unperturbed\n'
    # rows RUNS R SEED TABLE FILE PUBLISHED [N ...]: the case (b) rows of FILE at
    # each N (all of sizes by default), "-" where FILE lacks one
    rows() {
        local runs=$1 R=$2 S=$3 t=$4 f=$5 p=$6
        shift 6
        awk -F'\t' -v runs="$runs" -v R="$R" -v S="$S" -v t="$t" -v want="${*:-$sizes}" -v unp="$tmp/r0.$t" "$lib"'
            FNR == 1 { file++; hdr = 0 } /^#/ { next }
            !hdr++ { header(); next }
            file == 1 && $1 == "b" { pe[$2] = $col["L1"]; pi[$2] = $col["iter"] }
            file == 2 && $1 == "b" { e[$2] = $col["L1"]; it[$2] = $col["iter"] }
            END { while ((getline line < unp) > 0) { split(line, u, "\t"); if (u[2] != "-") u0[u[1]] = u[2] "\t" u[3] }
                  n = split(want, N, " ")
                  for (i = 1; i <= n; i++) {
                      c = (N[i] in e) ? e[N[i]] : "-"; ci = (N[i] in it) ? it[N[i]] : "-"
                      same = R == 0 || c == "-" || !(N[i] in u0) ? "-" : u0[N[i]] == c "\t" ci ? "same" : "changed"
                      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", runs, R, S, t, N[i], c, ci,
                             fixed_point(c), pe[N[i]], pi[N[i]], same
                      if (R == 0) printf "%s\t%s\t%s\n", N[i], c, ci > unp } }' "$p" "$f"
    }
    rows sizes 0 - 3.3 "$res/table3.3.tsv" "$pub3"
    rows sizes 0 - 3.2 "$res/table3.2.tsv" "$pub2" 640
    for rs in 1e-15:1 1e-15:2 1e-9:1; do
        R=${rs%%:*} S=${rs#*:}
        "$bin/example2" --strategy lax-wendroff --guess-noise "$R" --seed "$S" --out-dir "$tmp/lw$R.$S" > /dev/null
        "$bin/example2" --strategy richardson --sizes 640 --guess-noise "$R" --seed "$S" --out-dir "$tmp/r$R.$S" > /dev/null
        rows sizes "$R" "$S" 3.3 "$tmp/lw$R.$S/table3.3.tsv" "$pub3"
        rows sizes "$R" "$S" 3.2 "$tmp/r$R.$S/table3.2.tsv" "$pub2" 640
    done
    for R in 1e-9 1e-6; do
        for S in $(seq 1 16); do
            "$bin/example2" --strategy lax-wendroff --sizes 320 --guess-noise "$R" --seed "$S" --out-dir "$tmp/s$R.$S" > /dev/null
            rows seeds "$R" "$S" 3.3 "$tmp/s$R.$S/table3.3.tsv" "$pub3" 320
        done
    done
    ;;
treatments)
    printf '# treatments: Category III nodes fixed by first order sweeps (first-order, refs. [7,16]) or by the paper'"'"'s treatments; Example 1 (Table 3.1) and Example 2 (Tables 3.2 and 3.3)\n'
    printf '# fitted_order: p of the fit L1 = C h^p over the N of this example, strategy and case (its .fit.tsv)\n'
    printf 'example\tstrategy\tcase\tN\tL1\tfitted_order\n'
    for s in first-order richardson; do
        "$bin/example1" --strategy $s --out-dir "$tmp/e1$s" > /dev/null
    done
    for s in first-order richardson lax-wendroff; do
        "$bin/example2" --strategy $s --out-dir "$tmp/e2$s" > /dev/null
    done
    for es in 1:first-order 1:richardson 2:first-order 2:richardson 2:lax-wendroff; do
        e=${es%%:*} s=${es#*:}
        t=table3.1
        [ $e = 2 ] && t=table3.2
        [ $s = lax-wendroff ] && t=table3.3
        awk -F'\t' -v e=$e -v s=$s "$lib"'
            FNR == 1 { file++; hdr = 0 } /^#/ { next }
            !hdr++ { header(); next }
            file == 1 && $col["quantity"] == "L1" { p[$col["case"]] = $col["p"]; next }
            file == 2 { printf "%s\t%s\t%s\t%s\t%s\t%s\n", e, s, $1, $2, $col["L1"], p[$1] }' \
            "$tmp/e$e$s/$t.fit.tsv" "$tmp/e$e$s/$t.tsv"
    done
    ;;
*) echo "usage: studies.sh eps-scan BINDIR PUBLISHED3 | richardson-box BINDIR PUBLISHED2 | exclude BINDIR PUBLISHED4 PUBLISHED5 RESULTS | guess BINDIR PUBLISHED2 PUBLISHED3 | roundoff BINDIR PUBLISHED2 PUBLISHED3 RESULTS | treatments BINDIR" >&2; exit 2 ;;
esac
