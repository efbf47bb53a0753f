/*
 * apitrace's call sets and call flags (callset.h).  The grammar and its
 * meaning follow apitrace's lib/trace/trace_callset.cpp: a range's step
 * counts from its start (0-10/2 is 0, 2, ..., 10), a frequency selects calls
 * by flag, and N- runs to the end.  Unlike apitrace, which exits quietly on a
 * bad call set, every error is reported; empty ranges (5-3) and step 0 are
 * errors too.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "callset.h"

typedef struct parser {
    const char *s, *start;
    char *err;
    size_t errlen;
} parser;

static int pfail(parser *p, const char *what)
{
    snprintf(p->err, p->errlen, "bad call set '%s': %s at offset %d", p->start, what,
             (int)(p->s - p->start));
    return -1;
}

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
static bool is_digit(char c) { return c >= '0' && c <= '9'; }
static bool is_lower(char c) { return c >= 'a' && c <= 'z'; }
static bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }

static void skip_space(parser *p)
{
    while (is_space(*p->s))
        p->s++;
}

static bool op(parser *p, char c)
{
    if (*p->s != c)
        return false;
    p->s++;
    skip_space(p);
    return true;
}

static int number(parser *p, uint64_t *v)
{
    if (!is_digit(*p->s))
        return pfail(p, "expected a call number");
    uint64_t x = 0;
    while (is_digit(*p->s)) {
        unsigned d = (unsigned)(*p->s++ - '0');
        if (x > (UINT64_MAX - d) / 10)
            return pfail(p, "call number too large");
        x = x * 10 + d;
    }
    skip_space(p);
    *v = x;
    return 0;
}

static int frequency(parser *p, unsigned *freq)
{
    const char *w = p->s;
    while (is_lower(*p->s))
        p->s++;
    size_t n = (size_t)(p->s - w);
#define IS(word) (n == strlen(word) && strncmp(w, word, n) == 0)
    if (IS("frame"))
        *freq = FS_CALL_END_FRAME;
    else if (IS("rendertarget") || IS("fbo"))
        *freq = FS_CALL_END_FRAME | FS_CALL_SWAP_RENDERTARGET;
    else if (IS("render") || IS("draw"))
        *freq = FS_CALL_RENDER;
    else {
        p->s = w;
        return pfail(p, n ? "unknown frequency (frame, draw, render, fbo, rendertarget)"
                          : "expected a frequency (frame, draw, render, fbo, rendertarget)");
    }
#undef IS
    skip_space(p);
    return 0;
}

static int add(fs_callset *cs, fs_callset_range r)
{
    if (cs->n == cs->cap) {
        size_t cap = cs->cap ? cs->cap * 2 : 8;
        fs_callset_range *nr = realloc(cs->ranges, cap * sizeof *nr);
        if (!nr)
            return -1;
        cs->ranges = nr;
        cs->cap = cap;
    }
    cs->ranges[cs->n++] = r;
    return 0;
}

static int parse_range(parser *p, fs_callset *cs)
{
    fs_callset_range r = {0, UINT64_MAX, 1, FS_CALLSET_ALL};
    if (is_lower(*p->s)) {
        if (frequency(p, &r.freq))
            return -1;
    } else {
        if (!op(p, '*')) {
            if (number(p, &r.start))
                return -1;
            if (op(p, '-')) {
                if (is_digit(*p->s) && number(p, &r.stop))
                    return -1;
            } else {
                r.stop = r.start;
            }
            if (r.start > r.stop)
                return pfail(p, "empty range (its start is after its end)");
        }
        if (op(p, '/')) {
            if (is_digit(*p->s)) {
                if (number(p, &r.step))
                    return -1;
                if (r.step == 0)
                    return pfail(p, "step 0");
            } else if (frequency(p, &r.freq)) {
                return -1;
            }
        }
    }
    if (add(cs, r))
        return pfail(p, "out of memory");
    return 0;
}

static int parse_text(fs_callset *cs, const char *text, const char *shown, char *err, size_t errlen)
{
    parser p = {text, shown ? shown : text, err, errlen};
    skip_space(&p);
    while (*p.s) {
        if (parse_range(&p, cs))
            return -1;
        op(&p, ',');
    }
    return 0;
}

int fs_callset_parse(fs_callset *cs, const char *spec, char *err, size_t errlen)
{
    if (!spec[strspn(spec, " \t\r\n,")]) {
        snprintf(err, errlen, "bad call set '%s': no call in it", spec);
        return -1;
    }
    /* As apitrace: comma-separated items; one starting with @ names a file. */
    const char *s = spec;
    for (;;) {
        size_t n = strcspn(s, ",");
        char *item = malloc(n + 1);
        if (!item) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        memcpy(item, s, n);
        item[n] = '\0';
        int rc;
        if (item[0] == '@') {
            FILE *f = fopen(item + 1, "rb");
            char *text = NULL;
            size_t len = 0;
            if (f) {
                fseek(f, 0, SEEK_END);
                long size = ftell(f);
                fseek(f, 0, SEEK_SET);
                text = size >= 0 && size < (1L << 26) ? malloc((size_t)size + 1) : NULL;
                if (text)
                    len = fread(text, 1, (size_t)size, f);
                fclose(f);
            }
            if (!text) {
                snprintf(err, errlen, "call set file '%s' cannot be read", item + 1);
                rc = -1;
            } else {
                text[len] = '\0';
                if (memchr(text, '\0', len)) {
                    snprintf(err, errlen, "call set file '%s' is not text", item + 1);
                    rc = -1;
                } else {
                    rc = parse_text(cs, text, NULL, err, errlen);
                }
            }
            free(text);
        } else {
            rc = parse_text(cs, item, NULL, err, errlen);
        }
        free(item);
        if (rc)
            return -1;
        if (!s[n])
            return 0;
        s += n + 1;
    }
}

bool fs_callset_contains(const fs_callset *cs, uint64_t no, unsigned flags)
{
    for (size_t i = 0; i < cs->n; i++) {
        const fs_callset_range *r = &cs->ranges[i];
        if (no >= r->start && no <= r->stop && (no - r->start) % r->step == 0 &&
            ((flags & r->freq) || r->freq == FS_CALLSET_ALL))
            return true;
    }
    return false;
}

void fs_callset_free(fs_callset *cs)
{
    free(cs->ranges);
    cs->ranges = NULL;
    cs->n = cs->cap = 0;
}

/* ---- call flags (apitrace's lib/trace/trace_parser_flags.cpp) ---- */

/* s is all of [0-9A-Z]* */
static bool only_digits_upper(const char *s)
{
    for (; *s; s++)
        if (!is_digit(*s) && !is_upper(*s))
            return false;
    return true;
}

/* s matches ([A-Z][a-z]+)* over n characters */
static bool words(const char *s, size_t n)
{
    size_t i = 0;
    while (i < n) {
        if (!is_upper(s[i++]))
            return false;
        size_t k = i;
        while (i < n && is_lower(s[i]))
            i++;
        if (i == k)
            return false;
    }
    return true;
}

/* s matches ([A-Z][a-zA-Z]*)? */
static bool opt_tail(const char *s)
{
    if (!*s)
        return true;
    if (!is_upper(*s))
        return false;
    for (s++; *s; s++)
        if (!is_upper(*s) && !is_lower(*s))
            return false;
    return true;
}

static const char *skip_word(const char *s, const char *w)
{
    size_t n = strlen(w);
    return strncmp(s, w, n) == 0 ? s + n : NULL;
}

/* gl([A-Z][a-z]+)*Draw(Range|Mesh)?(Arrays|Elements)([A-Z][a-zA-Z]*)? */
static bool draw_name(const char *s)
{
    for (const char *d = strstr(s, "Draw"); d; d = strstr(d + 1, "Draw")) {
        if (!words(s, (size_t)(d - s)))
            continue;
        const char *t = d + 4;
        const char *opts[] = {"Range", "Mesh", ""};
        for (int k = 0; k < 3; k++) {
            const char *u = skip_word(t, opts[k]);
            if (!u)
                continue;
            const char *v = skip_word(u, "Arrays");
            if (!v)
                v = skip_word(u, "Elements");
            if (v && opt_tail(v))
                return true;
        }
    }
    return false;
}

/* gl(CallLists?|Clear|End|DrawPixels|DrawTransformFeedback([A-Z][a-zA-Z]*)?|
 *    BlitFramebuffer|Rect[dfis]v?|EvalMesh[0-9]+)[0-9A-Z]* */
static bool misc_draw_name(const char *s)
{
    static const char *const plain[] = {"CallList", "Clear", "End", "DrawPixels", "BlitFramebuffer"};
    for (size_t i = 0; i < sizeof plain / sizeof plain[0]; i++) {
        const char *t = skip_word(s, plain[i]);
        if (t && (only_digits_upper(t) || (i == 0 && *t == 's' && only_digits_upper(t + 1))))
            return true;
    }
    const char *t = skip_word(s, "DrawTransformFeedback");
    if (t) {
        if (only_digits_upper(t))
            return true;
        /* ([A-Z][a-zA-Z]*) then [0-9A-Z]*: a capital, letters, then capitals and digits */
        if (is_upper(*t)) {
            const char *u = t + 1;
            while (is_upper(*u) || is_lower(*u))
                u++;
            for (const char *v = u; v >= t + 1; v--)
                if (only_digits_upper(v))
                    return true;
        }
        return false;
    }
    t = skip_word(s, "Rect");
    if (t && *t && strchr("dfis", *t)) {
        t++;
        if (only_digits_upper(t) || (*t == 'v' && only_digits_upper(t + 1)))
            return true;
    }
    t = skip_word(s, "EvalMesh");
    if (t && is_digit(*t))
        return only_digits_upper(t);
    return false;
}

unsigned fs_call_flags(const char *name)
{
    static const char *const swaps[] = {
        "eglSwapBuffers", "eglSwapBuffersWithDamageEXT", "eglSwapBuffersWithDamageKHR",
        "glXSwapBuffers", "glXSwapBuffersMscOML", "wglSwapBuffers", "wglSwapLayerBuffers",
        "wglSwapMultipleBuffers",
    };
    if (strncmp(name, "gl", 2) == 0 && (draw_name(name + 2) || misc_draw_name(name + 2)))
        return FS_CALL_RENDER;
    const char *t = skip_word(name, "glBindFramebuffer");
    if (t && only_digits_upper(t))
        return FS_CALL_SWAP_RENDERTARGET;
    for (size_t i = 0; i < sizeof swaps / sizeof swaps[0]; i++)
        if (strcmp(name, swaps[i]) == 0)
            return FS_CALL_END_FRAME | FS_CALL_SWAP_RENDERTARGET;
    if (strcmp(name, "CGLFlushDrawable") == 0 || strcmp(name, "glFrameTerminatorGREMEDY") == 0)
        return FS_CALL_END_FRAME;
    return 0;
}
