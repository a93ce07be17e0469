#!/bin/bash
# output-safety.sh [BIN] -- programs meet hostile output locations.
#
# Each program below is run with its output name taken by a FIFO, a
# symbolic link, a copy of the null device (mknod) or a directory, with a
# read-only output directory (a read-only tmpfs), a missing one (or a file
# in the way of one) and a full disk (a 64 KiB tmpfs, filled up or left
# to fill).  Every run must exit non-zero with exactly one line on stderr,
# leave the special file as it was and leave no *.tmp.* file.  Cases that
# need mount or mknod are skipped with a message where those are not
# permitted.  The last line is "output-safety: N passed, M failed".
set -u
bin=$(cd "${1:-build/bin}" && pwd) || exit 2
work=$(mktemp -d "${TMPDIR:-/tmp}/hj-output-safety.XXXXXX") || exit 1
mounts=()
cleanup() {
    local m
    for m in "${mounts[@]}"; do umount "$m" 2>/dev/null; done
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM
pass=0 fail=0 skip=0
shopt -s nullglob globstar

# Programs: a label, the output name the program writes first into the
# output directory, whether it creates that directory (mkdir -p), and its
# command line with @D for the directory.
progs=(
    "eikonal|phi.tsv|0|$bin/paper1_fastsweeping/eikonal --speed-const 1 --source 0,0 --N 100 --out @D/phi.tsv"
    "example1|table3.1.tsv|1|$bin/paper1_fastsweeping/example1 --sizes 8 --grid-N 80 --out-dir @D"
    "fig21_shapes|fig21_1d.tsv|1|$bin/paper2_toolbox/fig21_shapes --out-dir @D"
    "hjtime|t.tsv|1|$bin/common/tools/hjtime @D/t.tsv label -- true"
    "eikonal-vtk|T.vtk|0|$bin/paper1_fastsweeping/eikonal --speed-const 1 --domain 0,1,0,1,0,1 --N 24 --source 0,0,0 --out @D/T.vtk"
)

# run LABEL DIR CMD: run CMD (@D replaced by DIR) in $work/cwd; sets $why
# to what is wrong ("" when it failed cleanly: non-zero status, one line
# on stderr, no temporary under DIR).
run() {
    local label=$1 dir=$2 cmd=${3//@D/$2}
    mkdir -p "$work/cwd"
    # shellcheck disable=SC2086
    (cd "$work/cwd" && exec timeout 120 $cmd) >"$work/out" 2>"$work/err" </dev/null
    local rc=$? all="" tmp=("$dir"/**/*.tmp.*)
    IFS= read -r -d '' all <"$work/err"
    why=""
    if [ $rc -eq 124 ]; then why="still running after 120 s"
    elif [ $rc -eq 0 ]; then why="exit status 0"
    elif [[ $all != *$'\n' || ${all%$'\n'} == *$'\n'* ]]; then why="stderr is not one line: $(head -c 300 "$work/err")"
    elif [ ${#tmp[@]} -ne 0 ]; then why="temporary left: ${tmp[*]}"
    fi
}

# verdict CASE LABEL EXTRA: count the case; EXTRA is a further failure.
verdict() {
    local w=${why:-$3}
    if [ -z "$w" ]; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL $1 ($2): $w"
        sed 's/^/    stderr: /' "$work/err" | head -3
    fi
}

skipped() {
    skip=$((skip + 1))
    echo "skipped: $1 ($2)"
}

# fresh: an empty output directory
fresh() {
    rm -rf "$work/d" && mkdir -p "$work/d"
}

# A tmpfs of 64 KiB at $work/d, read-only with "ro"; fails when mounting
# is not permitted.
tmpfs_d() {
    fresh
    mount -t tmpfs -o "size=64k${1:+,$1}" tmpfs "$work/d" 2>/dev/null || return 1
    mounts+=("$work/d")
}

untmpfs_d() {
    umount "$work/d" && unset 'mounts[${#mounts[@]}-1]'
}

for p in "${progs[@]}"; do
    IFS='|' read -r label name makes cmd <<<"$p"
    d=$work/d

    fresh && mkfifo "$d/$name"
    run "$label" "$d" "$cmd"
    extra=""
    [ -p "$d/$name" ] || extra="the FIFO was replaced"
    verdict fifo "$label" "$extra"

    fresh && echo keep >"$work/target" && ln -s "$work/target" "$d/$name"
    run "$label" "$d" "$cmd"
    extra=""
    [ -L "$d/$name" ] && [ "$(readlink "$d/$name")" = "$work/target" ] && [ "$(cat "$work/target")" = keep ] ||
        extra="the link or its target changed"
    verdict symlink "$label" "$extra"

    fresh
    if mknod "$d/$name" c 1 3 2>/dev/null; then
        run "$label" "$d" "$cmd"
        extra=""
        [ -c "$d/$name" ] && [ "$(stat -c %t,%T "$d/$name")" = "1,3" ] || extra="the device node changed"
        verdict null-device "$label" "$extra"
    else
        skipped null-device "$label: mknod not permitted"
    fi

    fresh && mkdir "$d/$name" && echo keep >"$d/$name/inside"
    run "$label" "$d" "$cmd"
    extra=""
    [ -d "$d/$name" ] && [ "$(cat "$d/$name/inside")" = keep ] || extra="the directory changed"
    verdict directory "$label" "$extra"

    # A missing directory: a program given a path fails; one that
    # creates it meets a file in the way instead.
    fresh && echo keep >"$d/file"
    if [ "$makes" = 1 ]; then
        run "$label" "$d/file/sub" "$cmd"
        verdict file-in-the-way "$label" ""
    else
        run "$label" "$d/missing" "$cmd"
        extra=""
        [ -e "$d/missing" ] && extra="the missing directory was created"
        verdict missing-dir "$label" "$extra"
    fi

    if tmpfs_d ro; then
        run "$label" "$d" "$cmd"
        verdict read-only-dir "$label" ""
        untmpfs_d
    else
        skipped read-only-dir "$label: mount not permitted"
    fi

    if tmpfs_d; then
        # filled up first: the first write fails
        cat /dev/zero >"$d/filler" 2>/dev/null
        run "$label" "$d" "$cmd"
        extra=""
        [ -e "$d/$name" ] && extra="$name written on a full disk"
        verdict full-disk "$label" "$extra"
        untmpfs_d
    else
        skipped full-disk "$label: mount not permitted"
    fi
done

# A disk that fills while the outputs are written: eikonal's 250 KB grid
# and 170 KB VTK volume,
# and fig21_shapes, whose pair of 3-D files meets the end of 2 MiB.
# The output being written then must not appear under its final name.
for c in "eikonal|64k|phi.tsv|${progs[0]#*|*|*|}" "eikonal-vtk|64k|T.vtk|${progs[4]#*|*|*|}" "fig21_shapes|2m|fig21_3d.dat|${progs[2]#*|*|*|}"; do
    IFS='|' read -r label size partial cmd <<<"$c"
    fresh
    if mount -t tmpfs -o "size=$size" tmpfs "$d" 2>/dev/null; then
        mounts+=("$d")
        run "$label" "$d" "$cmd"
        extra=""
        [ -e "$d/$partial" ] && extra="a partial $partial under its final name"
        verdict disk-fills-up "$label" "$extra"
        untmpfs_d
    else
        skipped disk-fills-up "$label: mount not permitted"
    fi
done

echo "output-safety: $pass passed, $fail failed, $skip skipped"
[ $fail -eq 0 ]
