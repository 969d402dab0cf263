/* ssao_readback.c - see ssao_readback.h. */
#include "ssao_readback.h"

#include "app_embed.h"
#include "chapters.h"

#include <stdlib.h>

bool ssao_readback(const gpu_scene *gs, const char *radius, const char *samples, const char *blur,
                   unsigned char *rgba)
{
    const char *args[] = {"--view", atoi(blur) > 0 ? "ao-blurred" : "ao", "--ao-radius", radius, "--ao-samples",
                          samples, "--ao-blur", blur, NULL};
    app_embed *e = NULL;
    bool ok = app_embed_open(&chapter_17, args, gs, &e) && app_embed_frame(e, gs, false, NULL) &&
              fbo_read_rgba8(app_embed_target(e), 0, rgba);
    app_embed_close(e);
    return ok;
}
