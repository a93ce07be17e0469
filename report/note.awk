# note.awk -- render a note template against a results directory.
#
#   awk -v dir=RESULTS -f report/note.awk TEMPLATE
#
# A note is the prose a program's data needs in the report (what a table
# shows, what its numbers mean).  Programs write only data (TSV with a header
# row; lines starting with '#' are comments); the prose lives in a template
# beside the program (<paper>/notes/NAME.md), and every number in it comes
# from the data through one of these placeholders:
#
#   {{table FILE [where SEL] [; SPEC; SPEC ...]}}   (alone on its line)
#       the rows of FILE as a Markdown table; each SPEC is
#       "COLUMN [FORMAT] [= TITLE]" (default: every column, as written)
#   {{value FILE where SEL; COLUMN [FORMAT]}}
#       one cell (SEL must pick exactly one row)
#   {{sum|min|max|rows FILE [where SEL] [; COLUMN [FORMAT]]}}
#       over the selected rows (rows: how many there are)
#
# SEL is "COL=VALUE, COL=VALUE ..." (equal as text, or as numbers when both
# are numbers).  FORMAT is a printf format (%.3g, %.1f, %d ...), applied to
# numeric cells only.  A file, row or column that is not there is rendered as
# **missing: ...** and the exit status is 1, so the report builder can tell.
function trim(s) { gsub(/^[ \t]+|[ \t]+$/, "", s); return s }
function isnum(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
function fmt(v, f) { return (f != "" && isnum(v)) ? sprintf(f, v + 0) : v }
function miss(what) { bad = 1; return "**missing: " what "**" }

# Read FILE into T[f, r, c] (rows 1..T[f, "n"], columns by name in H[f, name]).
function load(f,   path, line, n, i, r, a) {
    if ((f, "n") in T) return 1
    path = dir "/" f
    r = 0; n = -1
    while ((getline line < path) > 0) {
        if (line ~ /^#/ || line == "") continue
        if (n < 0) {
            n = split(line, a, "\t")
            for (i = 1; i <= n; i++) { H[f, a[i]] = i; T[f, 0, i] = a[i] }
            T[f, "nc"] = n
            continue
        }
        r++; split(line, a, "\t")
        for (i = 1; i <= n; i++) T[f, r, i] = a[i]
    }
    close(path)
    if (n < 0) return 0
    T[f, "n"] = r
    return 1
}

# Parse "FILE [where SEL] [; rest]" into P_file, P_sel, P_rest.
function parse(s,   k) {
    P_rest = ""
    k = index(s, ";")
    if (k) { P_rest = substr(s, k + 1); s = substr(s, 1, k - 1) }
    s = trim(s); P_sel = ""
    k = index(s, " where ")
    if (k) { P_sel = trim(substr(s, k + 7)); s = trim(substr(s, 1, k - 1)) }
    P_file = s
}

# The rows of P_file matching P_sel into R[1..nr]; "" or a missing message.
function select_rows(   nsel, sl, i, j, kv, c, ok, r, v) {
    nr = 0
    if (!load(P_file)) return miss(P_file)
    nsel = P_sel == "" ? 0 : split(P_sel, sl, ",")
    for (i = 1; i <= nsel; i++) {
        split(sl[i], kv, "=")
        SC[i] = trim(kv[1]); SV[i] = trim(kv[2])
        if (!((P_file, SC[i]) in H)) return miss(P_file " column " SC[i])
    }
    for (r = 1; r <= T[P_file, "n"]; r++) {
        ok = 1
        for (j = 1; j <= nsel && ok; j++) {
            v = T[P_file, r, H[P_file, SC[j]]]
            if (!(v == SV[j] || (isnum(v) && isnum(SV[j]) && v + 0 == SV[j] + 0))) ok = 0
        }
        if (ok) R[++nr] = r
    }
    return ""
}

# "COLUMN [FORMAT] [= TITLE]" into S_col, S_fmt, S_title.
function spec(s,   k, w) {
    S_title = ""
    k = index(s, "=")
    if (k) { S_title = trim(substr(s, k + 1)); s = substr(s, 1, k - 1) }
    split(trim(s), w, /[ \t]+/)
    S_col = w[1]; S_fmt = (w[2] ~ /^%/) ? w[2] : ""
    if (S_title == "") S_title = S_col
}

function table(s,   m, e, i, n, sp, r, line, out) {
    parse(s)
    if ((e = select_rows()) != "") return e
    if (!nr) return miss(P_file " rows where " P_sel)
    n = 0
    if (trim(P_rest) == "") {
        for (i = 1; i <= T[P_file, "nc"]; i++) { n++; C[n] = i; F[n] = ""; TT[n] = T[P_file, 0, i] }
    } else {
        m = split(P_rest, sp, ";")
        for (i = 1; i <= m; i++) {
            if (trim(sp[i]) == "") continue
            spec(sp[i])
            if (!((P_file, S_col) in H)) return miss(P_file " column " S_col)
            n++; C[n] = H[P_file, S_col]; F[n] = S_fmt; TT[n] = S_title
        }
    }
    line = "|"; for (i = 1; i <= n; i++) line = line " " TT[i] " |"
    out = line "\n|"; for (i = 1; i <= n; i++) out = out "---|"
    for (r = 1; r <= nr; r++) {
        line = "|"
        for (i = 1; i <= n; i++) line = line " " fmt(T[P_file, R[r], C[i]], F[i]) " |"
        out = out "\n" line
    }
    return out
}

function reduce(op, s,   e, r, v, acc, c, have) {
    parse(s)
    if ((e = select_rows()) != "") return e
    if (op == "rows") return nr
    spec(P_rest)
    if (!((P_file, S_col) in H)) return miss(P_file " column " S_col)
    c = H[P_file, S_col]
    if (op == "value") {
        if (nr != 1) return miss(P_file " one row where " P_sel " (" nr " match)")
        return fmt(T[P_file, R[1], c], S_fmt)
    }
    have = 0
    for (r = 1; r <= nr; r++) {
        v = T[P_file, R[r], c]
        if (!isnum(v)) continue
        v += 0
        if (!have) { acc = v; have = 1; continue }
        if (op == "sum") acc += v
        else if (op == "max" && v > acc) acc = v
        else if (op == "min" && v < acc) acc = v
    }
    if (!have) return miss(P_file " numbers in " S_col)
    return fmt(acc, S_fmt)
}

function expand(body,   w, rest) {
    body = trim(body)
    w = body; sub(/[ \t].*/, "", w)
    rest = substr(body, length(w) + 1)
    if (w == "table") return table(rest)
    if (w == "value" || w == "sum" || w == "min" || w == "max" || w == "rows") return reduce(w, rest)
    bad = 1
    return "**unknown placeholder: " w "**"
}

{
    line = $0; out = ""
    while ((i = index(line, "{{")) > 0) {
        j = index(substr(line, i + 2), "}}")
        if (!j) break
        out = out substr(line, 1, i - 1) expand(substr(line, i + 2, j - 1))
        line = substr(line, i + 2 + j + 1)
    }
    print out line
}

END { exit bad }
