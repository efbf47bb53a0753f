#!/bin/bash
# Re-captures the conformance corpus (tests/conformance/) from Debian's packages:
#   scripts/capture_conformance.sh piglit     piglit's GL 1.x fixed-function tests
#   scripts/capture_conformance.sh programs   glxgears and the listed xscreensaver GL hacks
# Needs: piglit, xscreensaver-gl, xscreensaver-gl-extra, mesa-utils, apitrace, xvfb
# (not needed by `make test`, which only replays the committed traces).
# Each capture runs on llvmpipe under Xvfb with one llvmpipe thread.  Kept are
# traces that use no shader, framebuffer object or vertex array object (GL >= 2
# machinery; piglit's own glGetFramebufferAttachmentParameteriv queries of the
# window's bits are harmless) and, for piglit, tests that did not skip.
# The list of what was kept, with piglit's verdict, goes to MANIFEST.tsv.
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WHAT=${1:-piglit}
PIGLIT=${PIGLIT:-/usr/lib/x86_64-linux-gnu/piglit}
WORK=${WORK:-/tmp/fragsim-capture}
# Size limits keep the corpus near 20 MB (each trace carries apitrace's ~45 KB
# enum table): piglit traces up to 400 KB, program traces up to 1.5 MB.
PIGLIT_MAXBYTES=${PIGLIT_MAXBYTES:-400000}
MAXBYTES=${MAXBYTES:-1500000}
FORBIDDEN='gl(CreateShader|ShaderSource|UseProgram|CreateProgram|BindFramebuffer|GenFramebuffers|BindRenderbuffer|BindVertexArray|BlitFramebuffer|BindProgramARB|ProgramStringARB|CompressedTex|BindSampler|TexImage2DMultisample|DrawBuffers|BeginTransformFeedback|TexBuffer)[A-Z]*\('
export LP_NUM_THREADS=1
mkdir -p "$WORK"

uses_forbidden() {  # trace -> prints the first forbidden call, if any
    apitrace dump --color=never "$1" 2>/dev/null | grep -m1 -oE "$FORBIDDEN"
}

capture_piglit() {
    local out="$ROOT/tests/conformance/piglit" man="$ROOT/tests/conformance/piglit/MANIFEST.tsv"
    mkdir -p "$out"
    if [ -n "${ONLY:-}" ] && [ -f "$man" ]; then grep -vE "^[^	]*(${ONLY})" "$man" > "$man.new"
    else printf 'trace\tpiglit test\tcommand\tpiglit result on llvmpipe\n' > "$man.new"; fi
    "$ROOT/scripts/conformance_piglit_list.py" "$PIGLIT" | while IFS=$'\t' read -r name cmd; do
        local short
        short=$(echo "$name" | sed -E 's/^spec@//; s/^!opengl 1\.([0-5])@/gl1\1-/; s/@/-/g; s/[^A-Za-z0-9.+-]+/_/g')
        if [ -n "${ONLY:-}" ] && ! echo "$short" | grep -qE "$ONLY"; then continue; fi
        local t="$WORK/$short.trace" log="$WORK/$short.log"
        rm -f "$t"
        # shellcheck disable=SC2086
        PIGLIT_PLATFORM=glx timeout -s TERM 60 xvfb-run -a -s '-screen 0 1280x1024x24' \
            apitrace trace -o "$t" $PIGLIT/bin/$cmd -auto >"$log" 2>&1
        local result
        result=$(grep -oE '"result": *"[a-z]+"' "$log" | tail -n1 | sed -E 's/.*"([a-z]+)"$/\1/')
        [ -s "$t" ] || { echo "drop $short: no trace"; continue; }
        case "$result" in pass|fail|warn) ;; *) echo "drop $short: piglit result '${result:-none}'"; continue;; esac
        local size bad
        size=$(stat -c %s "$t")
        [ "$size" -le "$PIGLIT_MAXBYTES" ] || { echo "drop $short: $size bytes"; continue; }
        bad=$(uses_forbidden "$t")
        [ -z "$bad" ] || { echo "drop $short: calls ${bad%(}"; continue; }
        cp "$t" "$out/$short.trace"
        printf '%s\t%s\t%s\t%s\n' "$short.trace" "$name" "$cmd" "$result" >> "$man.new"
        echo "keep $short ($size bytes, $result)"
    done
    mv "$man.new" "$man"
}

# The programs the conformance issue lists (others are kept out of the
# repository on purpose: they are the independent acceptance check).
HACKS="atlantis boxed bubble3d cage carousel circuit dangerball discoball engine extrusion
flipflop gflux glblur glhanoi glknots glmatrix glplanet glschool gltext lament menger moebius
molecule morph3d pulsar queens rubik sierpinski3d stairs starwars stonerview superquadrics
winduprobot antinspect polyhedra spheremonics"
FRAMES=${FRAMES:-4}

capture_programs() {
    local out="$ROOT/tests/conformance/programs" man="$ROOT/tests/conformance/programs/MANIFEST.tsv"
    mkdir -p "$out"
    printf 'trace\tprogram\tcommand\tframes kept\n' > "$man.new"
    local p
    for p in glxgears $HACKS; do
        # xscreensaver 6 hacks create their context and swap through EGL:
        # `--api egl` records those calls, so frames end at eglSwapBuffers and
        # glretrace can make the context.  glxgears uses GLX.
        local bin args="" api=gl t="$WORK/$p.full.trace" trimmed="$WORK/$p.trace"
        if [ "$p" = glxgears ]; then bin=/usr/bin/glxgears
        else bin=/usr/libexec/xscreensaver/$p; args="-root"; api=egl; fi
        [ -x "$bin" ] || { echo "drop $p: $bin missing"; continue; }
        rm -f "$t" "$trimmed"
        # shellcheck disable=SC2086
        timeout -s TERM 30 xvfb-run -a -s '-screen 0 640x480x24' \
            sh -c "timeout -s TERM ${SECONDS_RUN:-4} apitrace trace --api $api -o '$t' $bin $args" >"$WORK/$p.log" 2>&1
        [ -s "$t" ] || { echo "drop $p: no trace"; continue; }
        local bad
        bad=$(uses_forbidden "$t")
        [ -z "$bad" ] || { echo "drop $p: calls ${bad%(}"; continue; }
        # The set-up and the first $FRAMES frames (apitrace keeps call numbers).
        apitrace trim --frames=0-$((FRAMES - 1)) -o "$trimmed" "$t" >/dev/null 2>&1 \
            || { echo "drop $p: trim failed"; continue; }
        local swaps size
        swaps=$(apitrace dump --color=never "$trimmed" | grep -cE '^[0-9]+ (glX|egl)SwapBuffers')
        [ "$swaps" -ge 2 ] || { echo "drop $p: only $swaps frames"; continue; }
        size=$(stat -c %s "$trimmed")
        [ "$size" -le "$MAXBYTES" ] || { echo "drop $p: $size bytes after trimming"; continue; }
        cp "$trimmed" "$out/$p.trace"
        printf '%s\t%s\t%s\t%s\n' "$p.trace" "$p" "$bin $args" "$swaps" >> "$man.new"
        echo "keep $p ($size bytes, $swaps frames)"
    done
    mv "$man.new" "$man"
}

case "$WHAT" in
    piglit) capture_piglit ;;
    programs) capture_programs ;;
    all) capture_piglit; capture_programs ;;
    *) echo "usage: $0 piglit|programs|all" >&2; exit 2 ;;
esac
