#!/usr/bin/python3
"""Lists the piglit tests the conformance corpus draws from: every test of
piglit's opengl profile in the GL 1.0-1.5 groups and in the groups of GL 1.x
fixed-function extensions, as "name<TAB>command" (command relative to
piglit's bin/).  Multisample variants are left out (a fixed-function model
has one sample).  scripts/capture_conformance.sh then keeps only the tests
whose captured trace uses no shader, framebuffer object or vertex array
object and that piglit did not skip."""
import gzip, re, sys, ast
import xml.etree.ElementTree as ET

PIGLIT = sys.argv[1] if len(sys.argv) > 1 else '/usr/lib/x86_64-linux-gnu/piglit'
GROUPS = re.compile(r'^spec@(!opengl 1\.[0-5]|arb_occlusion_query|ext_occlusion_query_boolean|'
                    r'arb_vertex_buffer_object|arb_point_parameters|ext_fog_coord|'
                    r'ext_texture_env_combine|arb_texture_env_crossbar|sgis_generate_mipmap|'
                    r'ext_texture_lod_bias|arb_multitexture|arb_window_pos|ext_secondary_color|'
                    r'ext_packed_pixels|ext_texture3d|ext_draw_range_elements|'
                    r'arb_texture_border_clamp|arb_texture_mirrored_repeat|ext_blend_color|'
                    r'ext_blend_minmax|ext_blend_subtract|ext_stencil_wrap|ext_texture_edge_clamp)@')

tree = ET.parse(gzip.open(PIGLIT + '/tests/opengl.xml.gz'))
for t in tree.getroot():
    name = t.get('name')
    if not GROUPS.match(name) or 'samples=' in name:
        continue
    # 20 variants of one vertex-count test: four of them (arrays and buffer
    # objects; triangles, lines, points) cover its paths.
    if 'drawarrays-vertex-count' in name and not re.search(
            r'(varray gl_triangles|vbo gl_triangles|varray gl_lines|varray gl_points)$', name):
        continue
    cmd = None
    for o in t:
        if o.get('name') == 'command':
            cmd = ast.literal_eval(o.get('value'))
    if not cmd or t.get('type') != 'gl':
        continue
    print(name + '\t' + ' '.join(cmd))
