/*
 * Logical operation (GL 1.5 spec 4.1.10, table 4.4) and glLogicOp.  With
 * GL_COLOR_LOGIC_OP enabled it replaces blending and applies bitwise to all
 * four 8-bit channels.
 */
#include "fragment_stages.h"

void fs_exec_LogicOp(fs_context *c, GLenum opcode)
{
    if (opcode < GL_CLEAR || opcode > GL_SET) {
        fs_error(c, GL_INVALID_ENUM);
        return;
    }
    c->frag.logic_op = opcode;
    fs_state_mark(c, GL_COLOR_BUFFER_BIT);
}

static inline unsigned logic(GLenum op, unsigned s, unsigned d)
{
    switch (op) {
    case GL_CLEAR: return 0;
    case GL_AND: return s & d;
    case GL_AND_REVERSE: return s & ~d;
    case GL_COPY: return s;
    case GL_AND_INVERTED: return ~s & d;
    case GL_NOOP: return d;
    case GL_XOR: return s ^ d;
    case GL_OR: return s | d;
    case GL_NOR: return ~(s | d);
    case GL_EQUIV: return ~(s ^ d);
    case GL_INVERT: return ~d;
    case GL_OR_REVERSE: return s | ~d;
    case GL_COPY_INVERTED: return ~s;
    case GL_OR_INVERTED: return ~s | d;
    case GL_NAND: return ~(s & d);
    default: return ~0u; /* GL_SET */
    }
}

void fs_logic_op_rgba8(GLenum op, const uint8_t src[4], uint8_t dst[4])
{
    for (int k = 0; k < 4; k++)
        dst[k] = (uint8_t)logic(op, src[k], dst[k]);
}
