/*
 * The vertex program's POW as llvmpipe evaluates it (pipeline/vp_pow.c).
 */
#ifndef FS_VP_POW_H
#define FS_VP_POW_H

/* x^y as exp2(log2(x) y) with gallivm's polynomials; 0 for x == 0 or NaN. */
float fs_vp_pow(float x, float y);

#endif
