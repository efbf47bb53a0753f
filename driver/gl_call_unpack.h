/*
 * Unpacking fs_call arguments into typed locals, shared by the model's
 * dispatcher (dispatch.c) and the OSMesa reference dispatcher
 * (osmesa_ref.c), so both execute exactly the same decoded call.
 * Private to the driver: include only in those files.
 */
#ifndef FS_GL_CALL_UNPACK_H
#define FS_GL_CALL_UNPACK_H
#include "gl_call.h"

#define FS_UP_INT(t, a) ((t)(a).i)
#define FS_UP_FLT(t, a) ((t)(a).d)
#define FS_UP_PTR(t, a) ((t)(a).p)
#define FS_UP_OUT(t, a) ((t)(a).out)
#define FS_UP_E FS_UP_INT
#define FS_UP_BM FS_UP_INT
#define FS_UP_B FS_UP_INT
#define FS_UP_I FS_UP_INT
#define FS_UP_U FS_UP_INT
#define FS_UP_SZ FS_UP_INT
#define FS_UP_UB FS_UP_INT
#define FS_UP_BY FS_UP_INT
#define FS_UP_S FS_UP_INT
#define FS_UP_US FS_UP_INT
#define FS_UP_F FS_UP_FLT
#define FS_UP_D FS_UP_FLT
#define FS_UP_CF FS_UP_FLT
#define FS_UP_CD FS_UP_FLT
#define FS_UP_AF FS_UP_PTR
#define FS_UP_AD FS_UP_PTR
#define FS_UP_AI FS_UP_PTR
#define FS_UP_AU FS_UP_PTR
#define FS_UP_AUB FS_UP_PTR
#define FS_UP_ABY FS_UP_PTR
#define FS_UP_AS FS_UP_PTR
#define FS_UP_AUS FS_UP_PTR
#define FS_UP_BLOB FS_UP_PTR
#define FS_UP_CPTR FS_UP_PTR
#define FS_UP_OV FS_UP_OUT
#define FS_UP_OF FS_UP_OUT
#define FS_UP_OD FS_UP_OUT
#define FS_UP_OI FS_UP_OUT
#define FS_UP_OUS FS_UP_OUT
#define FS_UP_OU FS_UP_OUT
#define FS_UP_OB FS_UP_OUT
#define FS_UP_OUB FS_UP_OUT
#define FS_UP_IP FS_UP_INT
#define FS_UP_OP FS_UP_OUT
#define FS_UP_AP FS_UP_PTR
#define FS_LOCAL(k, kind, name, cnt) FS_CT_##kind name = FS_UP_##kind(FS_CT_##kind, call->a[k]);

#define FS_ESIZE_OV 1
#define FS_ESIZE_OF sizeof(GLfloat)
#define FS_ESIZE_OD sizeof(GLdouble)
#define FS_ESIZE_OI sizeof(GLint)
#define FS_ESIZE_OU sizeof(GLuint)
#define FS_ESIZE_OB sizeof(GLboolean)
#define FS_ESIZE_OUB 1
#define FS_ESIZE_OUS sizeof(GLushort)
#define FS_ESIZE_OP sizeof(GLvoid *)
#define FS_ESIZE_IP 0
#define FS_ESIZE_AF 0
#define FS_ESIZE_AD 0
#define FS_ESIZE_AI 0
#define FS_ESIZE_AU 0
#define FS_ESIZE_AUB 0
#define FS_ESIZE_ABY 0
#define FS_ESIZE_AS 0
#define FS_ESIZE_AUS 0
#define FS_ESIZE_BLOB 0
#define FS_ESIZE_E 0
#define FS_ESIZE_BM 0
#define FS_ESIZE_B 0
#define FS_ESIZE_I 0
#define FS_ESIZE_U 0
#define FS_ESIZE_SZ 0
#define FS_ESIZE_UB 0
#define FS_ESIZE_BY 0
#define FS_ESIZE_S 0
#define FS_ESIZE_US 0
#define FS_ESIZE_F 0
#define FS_ESIZE_D 0
#define FS_ESIZE_CF 0
#define FS_ESIZE_CD 0
#define FS_ESIZE_CPTR 0
#define FS_ESIZE_AP 0
#define FS_ANAME(k, kind, name, cnt) , name

/* Drops the leading comma FS_ANAME leaves, for calls without a context. */
#define FS_REST_(first, ...) __VA_ARGS__
#define FS_CALL_ARGS(...) FS_REST_(__VA_ARGS__)
#endif
