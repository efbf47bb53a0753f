#!/bin/bash
# fragsim sweep: a 2x2 grid on a tiny scene gives 4 CSV rows with the axis
# values as written in the spec, each job's statistics file records exactly
# those values as its effective config (read back with grep, not with the
# sweep's own JSON reader), a bad axis key fails with file:line like the
# config parser, a failing job is reported while the others are gathered,
# the CSV is the same across runs and runners except run time, and the
# Slurm script covers every job.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${SCENEGEN:?}"
# A private copy: other builds relinking build/ must not change the program
# between the jobs of one sweep (scenegen is found next to fragsim).
mkdir -p "$WORK/bin" && cp "$FRAGSIM" "$SCENEGEN" "$WORK/bin/" || exit 1
FRAGSIM=$WORK/bin/fragsim SCENEGEN=$WORK/bin/scenegen

grid_spec() { # OUT -> spec path
    cat >"$WORK/grid.ini" <<EOF
[sweep]
name = grid
out = $1

[traces]
scene = demo:small   ; generated on demand

[axis.occlusion.engines]
values = 1, 4

[axis.occlusion.max_tiles]
values = 16,100

[output]
stats = totals.triangles_rasterized
ratio.frags_per_tri = fragments / triangles_rasterized
EOF
    echo "$WORK/grid.ini"
}

# CSV without the run_time_s column (the only one allowed to change).
no_time() {
    local col
    col=$(head -n 1 "$1" | tr ',' '\n' | grep -n '^run_time_s$' | cut -d: -f1)
    [ -n "$col" ] || fail "no run_time_s column in $1"
    cut -d, -f"$col" --complement "$1"
}

test_grid_2x2() {
    local out="$WORK/g1" spec
    spec=$(grid_spec "$out")
    "$FRAGSIM" sweep "$spec" >"$WORK/log" 2>&1 || { cat "$WORK/log"; fail "sweep failed"; }
    grep -qE "ran 4 jobs with (GNU parallel|the built-in process pool)" "$WORK/log" || fail "runner not named: $(cat "$WORK/log")"
    [ "$(wc -l <"$out/results.csv")" -eq 5 ] || fail "expected header + 4 rows: $(cat "$out/results.csv")"
    head -n 1 "$out/results.csv" | grep -q '^job,trace,occlusion.engines,occlusion.max_tiles,status,' ||
        fail "header: $(head -n 1 "$out/results.csv")"
    local want="0 1 16
1 1 100
2 4 16
3 4 100"
    [ "$(tail -n +2 "$out/results.csv" | awk -F, '{print $1, $3, $4}')" = "$want" ] ||
        fail "axis values: $(cat "$out/results.csv")"
    [ "$(tail -n +2 "$out/results.csv" | cut -d, -f5 | sort -u)" = ok ] || fail "status: $(cat "$out/results.csv")"
    local j e t
    for j in 0 1 2 3; do
        e=$(sed -n "$((j + 2))p" "$out/results.csv" | cut -d, -f3)
        t=$(sed -n "$((j + 2))p" "$out/results.csv" | cut -d, -f4)
        grep -q "\"occlusion.engines\": $e,\?$" "$out/jobs/$j/stats.json" || fail "job $j: engines is not $e"
        grep -q "\"occlusion.max_tiles\": $t,\?$" "$out/jobs/$j/stats.json" || fail "job $j: max_tiles is not $t"
    done
    # The fragments column is the statistics file's total, job by job.
    local f0
    f0=$(grep -A 40 '"totals"' "$out/jobs/0/stats.json" | grep -m1 '"fragments_generated"' | tr -dc 0-9)
    [ "$(sed -n 2p "$out/results.csv" | cut -d, -f7)" = "$f0" ] || fail "fragments column != stats.json ($f0)"
    # The ratio column, recomputed here from the two columns it divides.
    tail -n +2 "$out/results.csv" | awk -F, '{ r = sprintf("%.4g", $7 / $9); if (r != $10) { print "row " NR ": " r " != " $10; exit 1 } }' ||
        fail "ratio column"
    head -n 1 "$out/results.csv" | grep -q ',triangles_rasterized,frags_per_tri$' || fail "ratio header"
    grep -q -- '--array=0-3$' "$out/slurm.sh" || fail "slurm.sh: $(cat "$out/slurm.sh")"
    grep -q -- '--sshlogin' "$out/parallel_ssh.sh" || fail "no --sshlogin line"
    [ "$(wc -l <"$out/jobs.tsv")" -eq 4 ] || fail "jobs.tsv lines"
}

test_deterministic_across_runs_and_runners() {
    local spec
    spec=$(grid_spec "$WORK/d1")
    "$FRAGSIM" sweep "$spec" >/dev/null 2>&1 || fail "first run"
    "$FRAGSIM" sweep --runner builtin -j 2 --out "$WORK/d2" "$spec" >"$WORK/log" 2>&1 || fail "builtin run"
    grep -q "built-in process pool" "$WORK/log" || fail "runner: $(cat "$WORK/log")"
    [ "$(no_time "$WORK/d1/results.csv")" = "$(no_time "$WORK/d2/results.csv")" ] || fail "CSV differs"
    "$FRAGSIM" sweep "$spec" >/dev/null 2>&1 || fail "third run"
    [ "$(no_time "$WORK/d1/results.csv")" = "$(no_time "$WORK/d2/results.csv")" ] || fail "CSV differs on rerun"
}

test_bad_axis_key() {
    printf '[traces]\nscene = demo\n\n[axis.occlusion.engines]\nvalues = 1\n[axis.occlusion.enginez]\nvalues = 1,2\n' >"$WORK/bad.ini"
    "$FRAGSIM" sweep --out "$WORK/b" "$WORK/bad.ini" 2>"$WORK/e"
    [ $? -eq 2 ] || fail "expected exit 2"
    grep -qF "$WORK/bad.ini:7: unknown key occlusion.enginez" "$WORK/e" || fail "message: $(cat "$WORK/e")"
    # the same words as the config parser gives for the same key in an INI file
    printf '[occlusion]\nenginez = 1\n' >"$WORK/c.ini"
    "$FRAGSIM" replay --config "$WORK/c.ini" --out "$WORK/b" x.trace 2>"$WORK/e2"
    local a b
    a=$(sed 's/.*:[0-9]*: //' "$WORK/e"); b=$(sed 's/.*:[0-9]*: //' "$WORK/e2")
    [ "$a" = "$b" ] || fail "sweep says '$a', config parser '$b'"
    printf '[traces]\nscene = demo\n[axis.occlusion.engines]\nvalues = 1, 65\n' >"$WORK/bad2.ini"
    "$FRAGSIM" sweep --out "$WORK/b" "$WORK/bad2.ini" 2>"$WORK/e"
    [ $? -eq 2 ] && grep -qF "bad2.ini:4: occlusion.engines: 65 is out of range" "$WORK/e" || fail "range: $(cat "$WORK/e")"
    [ ! -e "$WORK/b/jobs.tsv" ] || fail "a job list was written for a bad spec"
}

test_failing_job_reported_others_gathered() {
    echo "not a trace" >"$WORK/broken.trace"
    cat >"$WORK/f.ini" <<EOF
[sweep]
out = $WORK/f
[traces]
scene = demo
trace = $WORK/broken.trace
[axis.occlusion.engines]
values = 2
EOF
    "$FRAGSIM" sweep "$WORK/f.ini" >"$WORK/o" 2>"$WORK/e"
    [ $? -eq 1 ] || fail "expected exit 1"
    grep -qF "job 1 failed (exit 1): trace=broken occlusion.engines=2; log: $WORK/f/jobs/1/log.txt" "$WORK/e" ||
        fail "report: $(cat "$WORK/e")"
    [ -s "$WORK/f/jobs/1/log.txt" ] || fail "empty log"
    [ "$(sed -n 2p "$WORK/f/results.csv" | cut -d, -f1,2,4)" = "0,demo:small,ok" ] || fail "job 0: $(cat "$WORK/f/results.csv")"
    [ "$(sed -n 3p "$WORK/f/results.csv" | cut -d, -f4)" = failed ] || fail "job 1: $(cat "$WORK/f/results.csv")"
}

test_plot_and_no_run() {
    command -v gnuplot >/dev/null || skip "gnuplot not installed"
    local out="$WORK/p" spec
    spec=$(grid_spec "$out")
    printf '[plot.frags]\nx = occlusion.engines\ny = fragments\nseries = occlusion.max_tiles\n' >>"$spec"
    "$FRAGSIM" sweep --no-run "$spec" >/dev/null 2>&1 || fail "--no-run"
    [ -f "$out/jobs.tsv" ] && [ ! -e "$out/results.csv" ] || fail "--no-run ran jobs"
    [ -d "$out/jobs" ] || fail "no jobs/ directory for Slurm's --output"
    bash -n "$out/slurm.sh" && bash -n "$out/parallel_ssh.sh" || fail "cluster scripts are not valid shell"
    # a cluster would run each job so; then --gather collects them
    for j in 0 1 2 3; do "$FRAGSIM" sweep --run-job "$out/jobs.tsv" $j 2>"$WORK/e" || fail "run-job $j: $(cat "$WORK/e" "$out/jobs/$j/log.txt")"; done
    "$FRAGSIM" sweep --gather "$spec" >/dev/null 2>"$WORK/e" || fail "gather: $(cat "$WORK/e")"
    [ "$(tail -n +2 "$out/results.csv" | cut -d, -f5 | sort -u)" = ok ] || fail "gathered: $(cat "$out/results.csv")"
    [ -s "$out/frags.png" ] || fail "no plot"
    [ "$(head -c 4 "$out/frags.png" | od -An -c | tr -d ' ')" = '211PNG' ] || fail "not a PNG"
}

# A job's statistics file that is not JSON (cut short, say by a full disk
# on a cluster node): that job fails with the file, line and column named,
# the others are gathered.
test_bad_statistics_file_named() {
    local out="$WORK/bj" spec
    spec=$(grid_spec "$out")
    "$FRAGSIM" sweep --no-run "$spec" >/dev/null 2>&1 || fail "--no-run"
    for j in 0 1 2 3; do "$FRAGSIM" sweep --run-job "$out/jobs.tsv" $j 2>/dev/null || fail "run-job $j"; done
    head -c 300 "$out/jobs/2/stats.json" >"$WORK/cut.json" && mv "$WORK/cut.json" "$out/jobs/2/stats.json"
    printf '[1, 2]\n' >"$out/jobs/3/stats.json"
    "$FRAGSIM" sweep --gather "$spec" >/dev/null 2>"$WORK/e"
    [ $? -eq 1 ] || fail "expected exit 1: $(cat "$WORK/e")"
    grep -qE "job 2 failed \(statistics: $out/jobs/2/stats.json:[0-9]+:[0-9]+: malformed JSON: .+\)" "$WORK/e" ||
        fail "job 2: $(cat "$WORK/e")"
    grep -qF "job 3 failed (statistics: $out/jobs/3/stats.json: not a JSON object)" "$WORK/e" || fail "job 3: $(cat "$WORK/e")"
    [ "$(tail -n +2 "$out/results.csv" | cut -d, -f5 | tr '\n' ' ')" = "ok ok failed failed " ] ||
        fail "status column: $(cat "$out/results.csv")"
    # the gathered columns of the good jobs are the statistics file's numbers
    local t0
    t0=$(grep -A 40 '"totals"' "$out/jobs/0/stats.json" | grep -m1 '"triangles_rasterized"' | tr -dc 0-9)
    [ "$(sed -n 2p "$out/results.csv" | cut -d, -f9)" = "$t0" ] || fail "triangles column != stats.json ($t0)"
}

test_config_axis_and_mode() {
    printf '[occlusion]\nengines = 3\n' >"$WORK/a.ini"
    printf '[occlusion]\nengines = 5\nmax_tiles = 7\n' >"$WORK/b.ini"
    cat >"$WORK/cf.ini" <<EOF
[sweep]
out = $WORK/cf
mode = sampled
[traces]
scene = demo
[axis.config]
values = $WORK/a.ini, $WORK/b.ini
EOF
    "$FRAGSIM" sweep --mode functional "$WORK/cf.ini" >/dev/null 2>"$WORK/e" || fail "sweep: $(cat "$WORK/e")"
    ! grep -q -- '--mode' "$WORK/cf/jobs.tsv" || fail "--mode functional must override the spec's mode"
    grep -q '"occlusion.engines": 3,' "$WORK/cf/jobs/0/stats.json" || fail "job 0 did not read a.ini"
    grep -q '"occlusion.engines": 5,' "$WORK/cf/jobs/1/stats.json" || fail "job 1 did not read b.ini"
    grep -q '"occlusion.max_tiles": 7' "$WORK/cf/jobs/1/stats.json" || fail "job 1 did not read b.ini"
    [ "$(tail -n +2 "$WORK/cf/results.csv" | cut -d, -f3)" = "$WORK/a.ini
$WORK/b.ini" ] || fail "config column: $(cat "$WORK/cf/results.csv")"
    "$FRAGSIM" sweep --no-run --out "$WORK/cf2" "$WORK/cf.ini" >/dev/null 2>&1 || fail "--no-run"
    grep -qP '\t--mode\tsampled\t' "$WORK/cf2/jobs.tsv" || fail "spec mode not passed: $(cat "$WORK/cf2/jobs.tsv")"
    printf '[traces]\nscene = demo\n[axis.config]\nvalues = %s/none.ini\n' "$WORK" >"$WORK/cf3.ini"
    "$FRAGSIM" sweep --out "$WORK/cf3" "$WORK/cf3.ini" 2>"$WORK/e"
    [ $? -eq 2 ] && grep -q "none.ini: cannot open" "$WORK/e" || fail "missing config file: $(cat "$WORK/e")"
}

run_test test_grid_2x2
run_test test_config_axis_and_mode
run_test test_deterministic_across_runs_and_runners
run_test test_bad_axis_key
run_test test_failing_job_reported_others_gathered
run_test test_plot_and_no_run
run_test test_bad_statistics_file_named
finish
