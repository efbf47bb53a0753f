#!/usr/bin/python3
"""An independent replayer of apitrace traces on libOSMesa (llvmpipe), for the
conformance corpus's references.  It shares no code with fragsim: it reads the
trace through `apitrace pickle` (apitrace's own parser), calls each GL command
through ctypes with the signatures PyOpenGL declares, and reads the colour
buffer straight from OSMesa's client buffer at the requested calls.

  osmesa_replay.py TRACE OUTDIR CALL[,CALL...]

writes OUTDIR/NNNNNNNNNN.png (RGB, top row first, named by call number as
glretrace names its snapshots) after each listed call has executed.

Run with Debian's /usr/bin/python3 (python3-opengl) and PYOPENGL_PLATFORM=osmesa.
Why both this and glretrace: glretrace's first drawable on Xvfb is 32x32, so
its snapshots of a short trace's first draws are wrong
(shared/reference-notes.md); where both are valid they must agree."""
import ctypes
import os
import pickle
import subprocess
import sys

os.environ.setdefault('PYOPENGL_PLATFORM', 'osmesa')
import OpenGL  # noqa: E402
OpenGL.ERROR_CHECKING = False
OpenGL.ERROR_LOGGING = False
from OpenGL import osmesa  # noqa: E402
import OpenGL.raw.GL as rawgl  # noqa: E402
import importlib  # noqa: E402
import pkgutil  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pngio  # noqa: E402


class Pointer(int):
    """apitrace's opaque pointer value (an address in the traced process)."""


class Unpickler(pickle.Unpickler):
    def find_class(self, module, name):
        if module == 'unpickle' and name == 'Pointer':
            return Pointer
        raise pickle.UnpicklingError('unexpected class %s.%s' % (module, name))


def pickled_calls(trace):
    p = subprocess.Popen(['apitrace', 'pickle', trace], stdout=subprocess.PIPE)
    u = Unpickler(p.stdout)
    while True:
        try:
            yield u.load()
        except EOFError:
            break
    if p.wait() != 0:
        raise SystemExit('apitrace pickle failed on %s' % trace)


# ---- GL functions with their C signatures, from PyOpenGL's raw modules ----
ELEM = {'GLfloat': ctypes.c_float, 'GLdouble': ctypes.c_double, 'GLint': ctypes.c_int32,
        'GLuint': ctypes.c_uint32, 'GLshort': ctypes.c_int16, 'GLushort': ctypes.c_uint16,
        'GLbyte': ctypes.c_int8, 'GLubyte': ctypes.c_uint8, 'GLboolean': ctypes.c_uint8,
        'GLsizei': ctypes.c_int32, 'GLenum': ctypes.c_uint32, 'GLclampf': ctypes.c_float,
        'GLclampd': ctypes.c_double, 'GLchar': ctypes.c_char, 'GLvoidp': ctypes.c_void_p,
        'GLintptr': ctypes.c_ssize_t, 'GLsizeiptr': ctypes.c_ssize_t, 'GLbitfield': ctypes.c_uint32,
        'GLuint64': ctypes.c_uint64, 'GLint64': ctypes.c_int64}
_raw = {}


def _load_raw():
    for pkg in ('OpenGL.raw.GL.VERSION', 'OpenGL.raw.GL.ARB', 'OpenGL.raw.GL.EXT'):
        mod = importlib.import_module(pkg)
        for info in pkgutil.iter_modules(mod.__path__):
            if pkg.endswith('VERSION') and not info.name.startswith('GL_1_'):
                continue
            try:
                m = importlib.import_module(pkg + '.' + info.name)
            except Exception:  # a module PyOpenGL cannot load here
                continue
            for k, v in vars(m).items():
                if k.startswith('gl') and hasattr(v, 'argtypes') and k not in _raw:
                    _raw[k] = v


_fns = {}
_libosmesa = ctypes.CDLL('libOSMesa.so.8')


def gl_function(name):
    """(callable with plain ctypes argtypes, element type per argument) or None."""
    if name in _fns:
        return _fns[name]
    if not _raw:
        _load_raw()
    f = _raw.get(name)
    if f is None:
        _fns[name] = None
        return None
    sym = getattr(_libosmesa, name, None)  # libOSMesa exports the GL entry points itself
    addr = ctypes.cast(sym, ctypes.c_void_p).value if sym is not None else None
    if not addr:
        _fns[name] = None
        return None
    argtypes, elems = [], []
    for t in f.argtypes:
        tn = getattr(t, '__name__', '')
        if tn.endswith('Array'):
            argtypes.append(ctypes.c_void_p)
            elems.append(ELEM.get(tn[:-5], ctypes.c_uint8))
        elif t is ctypes.c_void_p or (isinstance(t, type) and issubclass(t, ctypes._Pointer)):
            argtypes.append(ctypes.c_void_p)
            elems.append(getattr(t, '_type_', None) if t is not ctypes.c_void_p else None)
        else:
            argtypes.append(t)
            elems.append(None)
    restype = f.restype if f.restype in (None, ctypes.c_uint, ctypes.c_int, ctypes.c_ubyte,
                                         ctypes.c_uint8, ctypes.c_uint32, ctypes.c_int32) else ctypes.c_void_p
    fn = ctypes.CFUNCTYPE(restype, *argtypes)(addr)
    _fns[name] = (fn, elems)
    return _fns[name]


# Calls that read state or talk to the window system: not replayed (a
# snapshot is taken from OSMesa's buffer, never through GL).
SKIP_PREFIX = ('glX', 'egl', 'wgl', 'glGet', 'glIs', 'glAreTexturesResident')
SKIP = {'glReadPixels', 'glFinish', 'glFlush', 'glGetError', 'glCheckFramebufferStatus'}
PIXEL_TYPES = {0x1400: ctypes.c_int8, 0x1401: ctypes.c_uint8, 0x1402: ctypes.c_int16,
               0x1403: ctypes.c_uint16, 0x1404: ctypes.c_int32, 0x1405: ctypes.c_uint32,
               0x1406: ctypes.c_float}


class Replayer:
    def __init__(self, width, height):
        self.w, self.h = width, height
        self.ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
        if not self.ctx:
            raise SystemExit('OSMesaCreateContextExt failed')
        self.buf = (ctypes.c_uint8 * (width * height * 4))()
        if not osmesa.OSMesaMakeCurrent(self.ctx, self.buf, 0x1401, width, height):
            raise SystemExit('OSMesaMakeCurrent failed')
        self.keep = []          # client memory GL may still point at
        self.maps = {}          # traced address of a mapped buffer -> real address
        self.unknown = {}

    def arg(self, value, elem, call_args):
        if value is None:
            return None
        if isinstance(value, Pointer):
            return int(value)
        if isinstance(value, (bytes, bytearray)):
            b = (ctypes.c_uint8 * max(len(value), 1)).from_buffer_copy(bytes(value) or b'\0')
            self.keep.append(b)
            return ctypes.addressof(b)
        if isinstance(value, str):
            b = ctypes.create_string_buffer(value.encode('latin-1'))
            self.keep.append(b)
            return ctypes.addressof(b)
        if isinstance(value, list):
            if elem is None:
                t = call_args.get('type')
                elem = PIXEL_TYPES.get(t, ctypes.c_float if any(isinstance(x, float) for x in value)
                                       else ctypes.c_int32)
            flat = []
            for x in value:
                flat.extend(x if isinstance(x, list) else [x])
            a = (elem * max(len(flat), 1))(*[int(x) if elem not in (ctypes.c_float, ctypes.c_double)
                                              else float(x) for x in flat])
            self.keep.append(a)
            return ctypes.addressof(a)
        if elem is not None:    # a single value given where an array is declared
            a = (elem * 1)(value)
            self.keep.append(a)
            return ctypes.addressof(a)
        return value

    def call(self, name, args, ret):
        if name == 'memcpy':
            d = dict(args)
            dest = int(d['dest'])
            base = max((b for b in self.maps if b <= dest), default=None)
            if base is None:
                raise SystemExit('memcpy into memory that was never mapped')
            src = bytes(d['src'])
            ctypes.memmove(self.maps[base] + dest - base, src, len(src))
            return
        if name.startswith(SKIP_PREFIX) or name in SKIP:
            return
        f = gl_function(name)
        if f is None:
            self.unknown[name] = self.unknown.get(name, 0) + 1
            return
        fn, elems = f
        d = dict(args)
        if name in ('glFeedbackBuffer', 'glSelectBuffer'):
            n = d['size']
            a = (ctypes.c_float if name == 'glFeedbackBuffer' else ctypes.c_uint32) * max(n, 1)
            b = a()
            self.keep.append(b)
            vals = [v for _, v in args]
            vals[-1] = ctypes.addressof(b)
            fn(*vals)
            return
        if name.startswith('glGen') or name.startswith('glCreate'):
            # Output arrays: OSMesa's fresh context hands out the same names
            # in the same order as the traced one (checked below).
            n = args[0][1]
            out = (ctypes.c_uint32 * max(n, 1))()
            r = fn(n, ctypes.addressof(out)) if len(args) == 2 else fn(*[v for _, v in args])
            traced = args[-1][1] if len(args) == 2 else ret
            if len(args) == 2 and isinstance(traced, list) and list(out)[:n] != traced:
                print('warning: %s gave %s, the trace %s' % (name, list(out)[:n], traced), file=sys.stderr)
            elif len(args) != 2 and r != ret:
                print('warning: %s gave %s, the trace %s' % (name, r, ret), file=sys.stderr)
            return
        vals = [self.arg(v, elems[i] if i < len(elems) else None, d) for i, (_, v) in enumerate(args)]
        r = fn(*vals)
        if name in ('glMapBuffer', 'glMapBufferARB', 'glMapBufferRange') and ret:
            self.maps[int(ret)] = r

    def snapshot(self, path):
        osmesa_fn = gl_function('glFinish')
        osmesa_fn[0]()
        w, h, src = self.w, self.h, bytes(self.buf)
        rgb = bytearray(w * h * 3)
        for y in range(h):   # OSMesa's rows are bottom first; PNG rows top first
            row = src[(h - 1 - y) * w * 4:(h - y) * w * 4]
            out = bytearray(w * 3)
            out[0::3], out[1::3], out[2::3] = row[0::4], row[1::4], row[2::4]
            rgb[y * w * 3:(y + 1) * w * 3] = out
        pngio.write_png(path, w, h, bytes(rgb))


def first_viewport(trace):
    for no, name, args, ret, flags in pickled_calls(trace):
        if name == 'glViewport':
            d = dict(args)
            return d['width'], d['height']
    raise SystemExit('%s: no glViewport, window size unknown' % trace)


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    trace, outdir, callset = sys.argv[1:]
    calls = {int(c) for c in callset.split(',') if c}
    os.makedirs(outdir, exist_ok=True)
    w, h = first_viewport(trace)
    r = Replayer(w, h)
    last = max(calls) if calls else -1
    for no, name, args, ret, flags in pickled_calls(trace):
        r.call(name, args, ret)
        if no in calls:
            r.snapshot(os.path.join(outdir, '%010d.png' % no))
        if no >= last:
            break
    for name, n in sorted(r.unknown.items()):
        print('warning: %s not replayed (%d calls): no signature known' % (name, n), file=sys.stderr)


if __name__ == '__main__':
    main()
