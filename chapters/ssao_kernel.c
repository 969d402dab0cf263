/* ssao_kernel.c - chapter 17's kernel and noise tile (ssao_kernel.h). */
#include "ssao_kernel.h"

#include "gl_util.h"
#include "shader_layout.h"

#include <cglm/cglm.h>
#include <math.h>

void ssao_kernel_make(rng *r, int samples, float kernel[][3])
{
    for (int i = 0; i < samples; i++) {
        /* u = sin^2 of the angle from the normal, uniform per stratum: cos-weighted directions */
        double u = (i + rng_unit(r)) / samples, phi = 2.0 * GLM_PI * rng_unit(r);
        double s = sqrt(u);
        kernel[i][0] = (float)(s * cos(phi)), kernel[i][1] = (float)(s * sin(phi));
        kernel[i][2] = (float)sqrt(1.0 - u);
    }
}

GLuint ssao_noise_create(rng *r)
{
    enum { N = SHADER_AO_NOISE_SIZE * SHADER_AO_NOISE_SIZE };
    int order[N];
    float turns[N][2];
    for (int i = 0; i < N; i++)
        order[i] = i;
    for (int i = N - 1; i > 0; i--) { /* Fisher-Yates */
        int j = rng_below(r, i + 1), t = order[i];
        order[i] = order[j], order[j] = t;
    }
    for (int i = 0; i < N; i++) {
        double angle = 2.0 * GLM_PI * (order[i] + 0.5) / N;
        turns[i][0] = (float)cos(angle), turns[i][1] = (float)sin(angle);
    }
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, SHADER_AO_NOISE_SIZE, SHADER_AO_NOISE_SIZE, 0, GL_RG, GL_FLOAT, turns);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    return gl_check("17 ssao noise tile") ? t : 0;
}
