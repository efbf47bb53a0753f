/*
 * Multisampling state (GL 1.5 spec 3.2.1, 4.1.3): glSampleCoverage.  The
 * window has no multisample buffer (GL_SAMPLE_BUFFERS 0), so by 3.2.1 and
 * 4.1.3 neither the enables (GL_MULTISAMPLE, GL_SAMPLE_*) nor the coverage
 * value affect rendering; they are stored for glGet and
 * glPushAttrib(GL_MULTISAMPLE_BIT).
 */
#include "context.h"

void fs_exec_SampleCoverage(fs_context *c, GLclampf value, GLboolean invert)
{
    /* 4.1.3: the value is clamped to [0, 1]; no error. */
    c->st.sample_coverage_value = value > 0.0f ? (value < 1.0f ? value : 1.0f) : 0.0f;
    c->st.sample_coverage_invert = invert != GL_FALSE;
    fs_state_mark(c, GL_MULTISAMPLE_BIT);
}
