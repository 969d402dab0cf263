/* cli_help.c - cli_print_help (cli.h): the --help text of a chapter, from its cli_desc; the
 * parsing is cli.c's. */
#include "cli.h"

#include "keys.h"

#include <stdio.h>
#include <string.h>

static void print_choices(FILE *stream, const char *const *choices)
{
    for (int i = 0; choices[i]; i++)
        fprintf(stream, "%s%s", i ? "|" : "", choices[i]);
}

/* Words of `text`, from `column` of a line that holds the option's name (padded: at_start, no space
 * before the first word), wrapped before HELP_WIDTH onto lines that start at HELP_COLUMN. */
#define HELP_COLUMN 27
#define HELP_WIDTH 92
static void print_wrapped(FILE *stream, const char *text, int column, bool at_start)
{
    bool line_start = at_start;
    while (*text) {
        int word = (int)strcspn(text, " ");
        if (!line_start && column + 1 + word > HELP_WIDTH) {
            fprintf(stream, "\n%*s", HELP_COLUMN, "");
            column = HELP_COLUMN;
        } else if (!line_start) {
            fputc(' ', stream);
            column++;
        }
        fprintf(stream, "%.*s", word, text);
        column += word;
        line_start = false;
        text += word;
        text += strspn(text, " ");
    }
    fputc('\n', stream);
}

/* A chapter's own option: its help, its choices and its default, wrapped. */
static void print_extra(FILE *stream, const cli_extra *e)
{
    char text[1024];
    int n = snprintf(text, sizeof text, "%s", e->help);
    for (int i = 0; e->choices && e->choices[i] && n < (int)sizeof text; i++)
        n += snprintf(text + n, sizeof text - (size_t)n, "%s%s", i ? "|" : " (", e->choices[i]);
    if (e->choices && n < (int)sizeof text)
        n += snprintf(text + n, sizeof text - (size_t)n, ")");
    if (e->default_value && n < (int)sizeof text)
        snprintf(text + n, sizeof text - (size_t)n, " (default %s)", e->default_value);
    int column = fprintf(stream, "  --%s %s", e->name, e->metavar);
    bool padded = column < HELP_COLUMN; /* else one space follows the name */
    if (padded)
        column += fprintf(stream, "%*s", HELP_COLUMN - column, "");
    print_wrapped(stream, text, column, padded);
}

void cli_print_help(const cli_desc *desc, FILE *stream)
{
    fprintf(stream, "usage: %s [options]\n%s\n\noptions:\n", desc->program, desc->summary);
    fprintf(stream,
            "  --help                   this text\n"
            "  --headless[=egl|osmesa]  no window: EGL surfaceless (default), or OSMesa\n"
            "  --size WxH               framebuffer size in pixels (default 800x600)\n"
            "  --frames N               frames to render, then exit (window default: until closed;\n"
            "                           headless default: 1)\n"
            "  --screenshot PATH        write the last frame as PNG (atomically)\n"
            "  --scene PATH             scene file (default: %s in the data folder)\n"
            "  --data-dir DIR           the folder with shaders/ and assets/ (default: $COURSE_DATA_DIR,\n"
            "                           else an installed prefix's share/deferred_course, else the\n"
            "                           source tree)\n",
            desc->default_scene ? desc->default_scene : CLI_DEFAULT_SCENE);
    if (desc->renderers) {
        fprintf(stream, "  --renderer NAME          ");
        print_choices(stream, desc->renderers);
        fprintf(stream, " (default %s)\n", desc->renderers[0]);
    }
    if (desc->views) {
        fprintf(stream, "  --view NAME              ");
        print_choices(stream, desc->views);
        fprintf(stream, " (default %s)\n", desc->views[0]);
    }
    for (int i = 0; i < CLI_MAX_EXTRAS && desc->extras[i].name; i++)
        print_extra(stream, &desc->extras[i]);
    fprintf(stream,
            "  --lights N               replace the scene's lights by N generated ones\n"
            "  --seed S                 seed of the light generator (default 1)\n"
            "  --time T                 animation time in seconds (default 0)\n"
            "  --paused                 window: start with the animation stopped at --time\n"
            "  --cutoff C               attenuation cut-off (default 5/256 = %.6f; 0 = exact, no cut-off)\n"
            "  --anisotropy N           a material image's most samples along a footprint, 1 to 16 (1: off;\n"
            "                           default 8, where the context filters anisotropically)\n"
            "  --bench                  time frames (glFinish + monotonic clock) and print a 'bench:' line\n"
            "                           (with the scene's features) and a 'programs:' line (every shader\n"
            "                           program the run compiled, with its defines)\n"
            "  --warmup N               untimed frames before --bench timing (default 3)\n"
            "  --gl-debug               report GL debug messages; any GL error fails the run\n"
            "  --resize-cycle N         after the first frame, resize N times and back; fail if GL\n"
            "                           objects leaked (window: resizes the window)\n"
            "  --minimise-cycle N       window: after the first frame, minimise and restore N times;\n"
            "                           fail if a frame was drawn while minimised or GL objects leaked\n"
            "                           (exit 77 when nothing can minimise it: no window manager)\n"
            "  --camera \"POSE\"          the scene's camera with these attributes replaced, as in a\n"
            "                           scene's camera line: \"eye X Y Z target X Y Z [up X Y Z] [fovy F]\n"
            "                           [near N] [far F]\" (fovy 0.01..180 degrees, near > 0, far / near\n"
            "                           at most 2^24: what a depth buffer can hold)\n"
            "  --falloff hard|windowed  how lights fade to their radius (default: the scene's, else hard):\n"
            "                           windowed multiplies by (1 - (d/r)^4)^2, so the cut-off leaves no step\n"
            "  --gbuffer LAYOUT         the G-buffer's formats (common/render/gbuffer.h, docs/02_mrt_gbuffer.md):\n"
            "                           compact       sRGB8 albedo + specular; normal in 2x12 bits +\n"
            "                                         shininess in RGBA8; D32F: 12 bytes/pixel (default)\n"
            "                           reference     sRGB8 albedo, RGBA16F normal + material, D32F: 16\n"
            "                           compact-d24s8 compact with a 24-bit depth and stencil: 12\n"
            "                           reversed-z    compact with a reversed float depth: 12 (GL 4.5 or\n"
            "                                         ARB_clip_control; chapters 02, 03, 11, 17, 19;\n"
            "                                         17 and 19's default without PBR materials)\n"
            "                           linear-albedo compact with linear RGBA8 albedo: 12\n"
            "                           oct8          compact with a 2x8-bit normal: 12\n"
            "                           oct16         compact with a 2x16-bit normal in RGBA16: 16\n"
            "  --compare MODE           off|split|difference: forward left of a divider and this chapter's\n"
            "                           renderer right of it, or their difference beyond 1/255 as a heat map (key M);\n"
            "                           forward is timed as its own pass, left out of the chapter's figure\n"
            "                           (with --bench: compare_forward_ms)\n"
            "  --overlay                the on-screen overlay from the start, also in --screenshot (key H)\n"
            "  --script FILE            timed keys and mouse events, as if typed (format:\n"
            "                           common/platform/input_script.h; the tests drive the window with it)\n"
            "  --gl-info                print the GL context's renderer, version and limits, then exit\n"
            "  --verbose                more log lines\n"
            "  --quiet                  no progress lines (written while frames take more than 2 s)\n",
            desc->default_cutoff);
    keys_print_help(stream, desc->program, desc->views != NULL);
    fprintf(stream, "\nshaders: built for the scene's features, so a scene pays only for what it uses: the light\n"
                    "kinds (point, spot), the material models (blinn-phong, metallic-roughness), the material\n"
                    "images (maps) and emissive; a chapter's shadows, occlusion and probes only while they are\n"
                    "on (common/gl/shader_features.h; --bench's 'features=' names a run's)\n");
    fprintf(stream, "\nexit codes: 0 ok, 1 runtime failure, 2 usage or input error, 77 no GL context\n");
}
