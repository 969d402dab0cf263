/* overlay.h - lines of text over a picture, drawn with stb_easy_font (stb's tiny vector font: the
 * glyphs come as quads, drawn here as triangles), on a translucent box in the top-left corner.
 *
 *   overlay_create(o)                          program, buffers
 *   overlay_destroy(o)
 *   overlay_draw(o, fbo, width, height, text, corner)
 *                                              `text` ('\n' between lines; characters outside
 *                                              printable ASCII shown as spaces) over framebuffer
 *                                              `fbo` of that size, in corner OVERLAY_TOP_LEFT or
 *                                              OVERLAY_TOP_RIGHT, scaled with the height (2x at
 *                                              480 px) so that it stays legible on a HiDPI window
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
    int quad_capacity;
    void *scratch; /* stb_easy_font's vertices before upload */
} overlay;

bool overlay_create(overlay *o);
void overlay_destroy(overlay *o);
void overlay_draw(overlay *o, GLuint fbo, int width, int height, const char *text, overlay_corner corner);

#endif
