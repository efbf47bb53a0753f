/*
 * Helpers for tests that write small apitrace traces with fragsim's trace
 * writer (driver/trace.h): argument values and one call.  Shared by
 * test_replay.c, test_errors.c and test_buffer_objects.c.
 */
#ifndef FS_TEST_TRACE_BUILD_H
#define FS_TEST_TRACE_BUILD_H
#include <string.h>
#include "../driver/trace.h"

static inline fs_tval tb_ival(int64_t v) { fs_tval x; memset(&x, 0, sizeof x); x.type = FS_TV_SINT; x.i = v; return x; }
static inline fs_tval tb_fval(double v) { fs_tval x; memset(&x, 0, sizeof x); x.type = FS_TV_FLOAT; x.d = v; return x; }
static inline fs_tval tb_eval(int64_t v, const char *name)
{
    fs_tval x = tb_ival(v);
    x.type = FS_TV_ENUM;
    x.enum_name = name;
    return x;
}

static inline fs_tval tb_blob(const void *p, size_t n)
{
    fs_tval x;
    memset(&x, 0, sizeof x);
    x.type = FS_TV_BLOB;
    x.str.ptr = (const char *)p;
    x.str.len = n;
    return x;
}
/* A pointer value of the traced program, as apitrace writes one. */
static inline fs_tval tb_opaque(uint64_t v)
{
    fs_tval x;
    memset(&x, 0, sizeof x);
    x.type = FS_TV_OPAQUE;
    x.u = v;
    return x;
}

/* Writes the call NAME(args[0..n-1]) returning *ret (NULL: nothing);
 * arguments are named a, b, c, ... */
static inline void tb_write_call_ret(fs_trace_writer *w, const char *name, int n, const fs_tval *args, uint32_t flags,
                                     const fs_tval *ret)
{
    static const char *const argnames[10] = {"a", "b", "c", "d", "e", "f", "g", "h", "i", "j"};
    fs_tcall c;
    memset(&c, 0, sizeof c);
    c.name = name;
    c.nargs = (unsigned)n;
    c.arg_names = argnames;
    c.args = args;
    c.flags = flags;
    if (ret) {
        c.has_ret = 1;
        c.ret = *ret;
    }
    fs_trace_write(w, &c);
}

static inline void tb_write_call(fs_trace_writer *w, const char *name, int n, const fs_tval *args, uint32_t flags)
{
    tb_write_call_ret(w, name, n, args, flags, NULL);
}
#endif
