/* overlay.h - lines of text over a picture, drawn with stb_easy_font (stb's tiny vector font: the
 * glyphs come as quads, drawn here as triangles), on a translucent box in the top-left corner.
 *
 *   overlay_create(o)                          program, buffers
 *   overlay_destroy(o)
 *   overlay_draw(o, fbo, width, height, text, corner, content_scale)
 *                                              `text` ('\n' between lines; characters outside
 *                                              printable ASCII shown as spaces) over framebuffer
 *                                              `fbo` of that size, in corner OVERLAY_TOP_LEFT or
 *                                              OVERLAY_TOP_RIGHT, scaled with the height and the
 *                                              screen's content scale (2x at 480 px on a 1x screen),
 *                                              never so large that a line of OVERLAY_MIN_COLUMNS
 *                                              characters would not fit; lines wider than the
 *                                              picture wrap (at a space, indented); a text taller
 *                                              than the picture is drawn smaller (down to 1x), and
 *                                              only lines below its bottom at 1x are cut, the last
 *                                              saying so and a warning logged once: the box
 *                                              never leaves the picture, and only it is dimmed.
 *                                              Any length: no buffer of a fixed size holds the
 *                                              text, and the quads' room grows with it
 *   overlay_draw_label(o, fbo, width, height, text, x, y, content_scale)
 *                                              one short line in its box with its top-left corner at
 *                                              pixel (x, y) from the top-left, kept inside the picture
 *                                              (the window marks a light added with G this way)
 *
 * The runner draws it into the picture the window shows, after the frame was timed and after
 * --screenshot read the picture (unless --overlay asks for it in the screenshot).
 */
#ifndef COMMON_OVERLAY_H
#define COMMON_OVERLAY_H

#include <glad/gl.h>
#include <stdbool.h>

typedef enum overlay_corner { OVERLAY_TOP_LEFT, OVERLAY_TOP_RIGHT } overlay_corner;

typedef struct overlay {
    GLuint program, vao, vertices, indices;
    int quad_capacity; /* quads the buffers hold now; they grow for a longer text */
    int lines_cut;     /* by the last overlay_draw: the warning is logged when it changes */
    void *scratch;     /* stb_easy_font's vertices before upload */
} overlay;

bool overlay_create(overlay *o);
void overlay_destroy(overlay *o);
#define OVERLAY_MIN_COLUMNS 64
void overlay_draw(overlay *o, GLuint fbo, int width, int height, const char *text, overlay_corner corner,
                  float content_scale);
void overlay_draw_label(overlay *o, GLuint fbo, int width, int height, const char *text, float x, float y,
                        float content_scale);

#endif
