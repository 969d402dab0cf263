/* renderer_tiled.h - deferred-tiled, chapter 10's frame for the renderer table and the benchmark
 * (chapters/10_tiled_deferred.c has the same steps, explained); renderers.c only.
 *
 *   ensure_tiled(r, gs)                     make r->tiled's programs and targets for gs's view
 *   draw_tiled(t, gs, target, count, &evaluations)
 *                                           one frame; evaluations: light-loop iterations when count
 *   tiled_destroy(t)
 * The GL-free culling it shares with the chapter (renderer_tile_*) is declared in renderers.h.
 */
#ifndef COMMON_RENDERER_TILED_H
#define COMMON_RENDERER_TILED_H

#include "renderers.h"

bool ensure_tiled(renderer_set *r, const gpu_scene *gs);
bool draw_tiled(renderer_tiled *t, const gpu_scene *gs, GLuint target, bool count, long *evaluations);
void tiled_destroy(renderer_tiled *t);

#endif
