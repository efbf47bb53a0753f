/*
 * The tokens of fragsim's GL extensions (the headers in glext/) against each other and
 * against the enum table traces are written with (driver/gl_enums.c): every
 * token value is used once, lies in a range no Mesa header uses, and has its
 * header name in the table, so a trace names it.  The headers are read as
 * text, so a token added to a header without a table row fails here.
 */
#include <stdint.h>
#include "check.h"
#include "../driver/gl_enums.h"

static const char *const headers[] = {
    "glext/GL_FRAGSIM_occlusion_unit.h",
    "glext/GL_FRAGSIM_mp_grid.h",
    "glext/GL_FRAGSIM_footprint_filter.h",
};

typedef struct token { char name[96]; uint32_t value; int header; } token;

/* `#define GL_NAME 0xVALUE` lines.  The extension's own flag macro (value 1)
 * is not a token, nor is a data value such as GL_OCCLUSION_LIST_END
 * (0xFFFFFFFF, a word in a hit list): GL enums are below 0x10000. */
static int read_tokens(token *out, int cap)
{
    int n = 0;
    for (int h = 0; h < (int)(sizeof headers / sizeof headers[0]); h++) {
        FILE *f = fopen(headers[h], "r");
        if (!f)
            return -1;
        char line[512];
        while (fgets(line, sizeof line, f)) {
            char name[96];
            unsigned value;
            if (sscanf(line, "#define %95s 0x%x", name, &value) == 2 && !strncmp(name, "GL_", 3) && value < 0x10000 && n < cap) {
                snprintf(out[n].name, sizeof out[n].name, "%s", name);
                out[n].value = value;
                out[n].header = h;
                n++;
            }
        }
        fclose(f);
    }
    return n;
}

TEST(tokens_distinct_and_private)
{
    token t[256];
    int n = read_tokens(t, 256);
    CHECK(n >= 25);
    for (int i = 0; i < n; i++) {
        /* 0x6000-0x6FFF: no token of Debian 12's GL/gl.h or GL/glext.h. */
        if (t[i].value < 0x6000 || t[i].value > 0x6FFF)
            CHECK_FAIL_("%s = 0x%X outside the private range", t[i].name, t[i].value);
        for (int j = i + 1; j < n; j++)
            if (t[i].value == t[j].value)
                CHECK_FAIL_("%s (%s) and %s (%s) share 0x%X", t[i].name, headers[t[i].header], t[j].name,
                            headers[t[j].header], t[i].value);
    }
}

TEST(tokens_named_in_trace_table)
{
    token t[256];
    int n = read_tokens(t, 256);
    CHECK(n >= 25);
    for (int i = 0; i < n; i++) {
        uint32_t v = 0;
        if (fs_gl_enum_value(t[i].name, &v) != 0 || v != t[i].value)
            CHECK_FAIL_("%s: enum table has value 0x%X, header 0x%X", t[i].name, v, t[i].value);
        const char *back = fs_gl_enum_name(t[i].value);
        if (!back || strcmp(back, t[i].name))
            CHECK_FAIL_("0x%X: enum table names it %s, header %s", t[i].value, back ? back : "(none)", t[i].name);
    }
}

TEST_LIST = {
    TEST_ENTRY(tokens_distinct_and_private),
    TEST_ENTRY(tokens_named_in_trace_table),
    TEST_END,
};

int main(int argc, char **argv) { return check_main(argc, argv, test_list); }
