/* bench_gbuffer_report.c - the G-buffer sweep's CSV and its section of bench.md (bench_gbuffer.h). */
#include "bench_gbuffer.h"
#include "bench_gbuffer_rows.h"

#include <math.h>

#define R bench_gbuffer_results_now

const char *const bench_gbuffer_scene_names[SCENES] = {"default", "city", "pbr_teapots"};
const char *const bench_gbuffer_band_names[3] = {"near", "middle", "far"};

static const char *format_name(GLenum f)
{
    switch (f) {
    case GL_SRGB8_ALPHA8: return "SRGB8_ALPHA8";
    case GL_RGBA8: return "RGBA8";
    case GL_RGBA16F: return "RGBA16F";
    case GL_RGBA16: return "RGBA16";
    case GL_DEPTH24_STENCIL8: return "D24S8";
    case GL_DEPTH_COMPONENT32F: return "D32F";
    default: return "?";
    }
}

static const char *depth_name(const gbuffer_layout *l)
{
    return l->depth == GBUFFER_DEPTH_D32F_REVERSED ? "D32F reversed"
                                                   : format_name(gbuffer_layout_depth_format(l, false));
}

static const char *normal_name(int encoding)
{
    switch (encoding) {
    case SHADER_GBUFFER_NORMAL_HALF: return "2 halves";
    case SHADER_GBUFFER_NORMAL_BYTES: return "2x8 bits";
    case SHADER_GBUFFER_NORMAL_PACKED: return "2x12 bits";
    default: return "2x16 bits";
    }
}

static void put(FILE *f, bool have, const char *fmt, double v)
{
    fputc(',', f);
    if (have && isfinite(v))
        fprintf(f, fmt, v);
    else
        fputs("NA", f);
}

bool bench_gbuffer_write_csv(const bench_state *st)
{
    char tmp[1024];
    FILE *f = bench_report_open_tmp(st->opt.out_dir, "bench_gbuffer.csv", tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(
        f, "scene,lights,layout,default,bytes,bytes_with_stencil,albedo_format,normal_format,normal_encoding,"
           "depth_format,width,height,frames,median_ms,geometry_ms,lighting_ms,normal_max_deg,"
           "normal_mean_deg,covered_pixels,other_surface_pixels");
    for (int b = 0; b < 3; b++)
        fprintf(f, ",%s_distance,%s_mean_error,%s_max_error", bench_gbuffer_band_names[b], bench_gbuffer_band_names[b], bench_gbuffer_band_names[b]);
    fprintf(f, ",vs_forward_max_8bit,vs_forward_pixels_over_1,vs_forward_mean_8bit,vs_forward_max_hdr,"
               "vs_forward_mean_hdr,max_abs_8bit,mean_abs_8bit,psnr_8bit,max_abs_hdr,mean_abs_hdr,psnr_hdr,"
               "vs_reference_max_8bit,vs_reference_pixels_over_1,R.pass_clock,note\n");
    for (int si = 0; si < SCENES; si++)
        for (int l = 0; R.scene_done[si] && l < GBUFFER_LAYOUT_COUNT; l++) {
            const layout_row *r = &R.rows[si][l];
            const gbuffer_layout *g = &gbuffer_layouts[l];
            bool m = r->measured;
            fprintf(f, "%s,%d,%s,%s,%d,%d,%s,%s,%s,%s,%d,%d,%d", bench_gbuffer_scene_names[si], r->lights, gbuffer_layout_name(g),
                    g == gbuffer_default_layout() ? "yes" : "no", gbuffer_layout_bytes(g, false),
                    gbuffer_layout_bytes(g, true), format_name(g->albedo_format),
                    format_name(g->normal_format), normal_name(g->normal_encoding), depth_name(g),
                    st->opt.width, st->opt.height, r->frames);
            put(f, m, "%.3f", r->frame_ms);
            put(f, m, "%.3f", r->geometry_ms);
            put(f, m, "%.3f", r->lighting_ms);
            put(f, m, "%.6f", r->normal_max);
            put(f, m, "%.6f", r->normal_mean);
            put(f, m, "%.0f", (double)r->covered);
            put(f, m, "%.0f", (double)r->other_surface);
            for (int b = 0; b < 3; b++) {
                put(f, m, "%.4g", r->bands[b].distance);
                put(f, m, "%.4g", r->bands[b].mean);
                put(f, m, "%.4g", r->bands[b].max);
            }
            put(f, m, "%.0f", r->vs_forward8.max_abs);
            put(f, m, "%.0f", (double)r->vs_forward8.over);
            put(f, m, "%.5f", r->vs_forward8.mean_abs);
            put(f, m, "%.6g", r->vs_forward_hdr.max_abs);
            put(f, m, "%.6g", r->vs_forward_hdr.mean_abs);
            bool x = m && r->have_exact;
            put(f, x, "%.0f", r->error8.max_abs);
            put(f, x, "%.5f", r->error8.mean_abs);
            put(f, x, "%.2f", r->error8.psnr);
            put(f, x, "%.6g", r->error_hdr.max_abs);
            put(f, x, "%.6g", r->error_hdr.mean_abs);
            put(f, x, "%.2f", r->error_hdr.psnr);
            put(f, m, "%.0f", r->vs_reference.max_abs);
            put(f, m, "%.0f", (double)r->vs_reference.over);
            fprintf(f, ",%s,%s\n", R.pass_clock ? R.pass_clock : "NA", r->note);
        }
    return bench_report_close_tmp(f, tmp, st->opt.out_dir, "bench_gbuffer.csv");
}

static void write_layout_table(FILE *f)
{
    fprintf(f, "| layout | RT0 (albedo) | RT1 (normal) | depth | bytes | with stencil | loses |\n"
               "|---|---|---|---|---|---|---|\n");
    for (int l = 0; l < GBUFFER_LAYOUT_COUNT; l++) {
        const gbuffer_layout *g = &gbuffer_layouts[l];
        fprintf(f, "| %s%s | %s | %s, %s | %s | %d | %d | %s |\n", gbuffer_layout_name(g),
                g == gbuffer_default_layout() ? " (default)" : "", format_name(g->albedo_format),
                format_name(g->normal_format), normal_name(g->normal_encoding), depth_name(g),
                gbuffer_layout_bytes(g, false), gbuffer_layout_bytes(g, true), g->loses);
    }
    fprintf(f, "\n");
}

void bench_gbuffer_write_md(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    fprintf(f,
            "\n## G-buffer layouts\n\n"
            "Chapter 07's frame (deferred-volumes, cut-off 5/256) with every layout of common/render/gbuffer.h, "
            "on each scene with its own lights, %dx%d; %d warm-up + %d timed frames per layout, layouts "
            "interleaved frame by frame; passes on the %s clock. Normal: angle between the decoded normal "
            "and the geometry pass's float normal. Position: distance between the position rebuilt from "
            "depth and the interpolated float position, mean / max in scene units, over the nearest, "
            "middle and farthest third of the covered pixels (their median distance from the eye in "
            "brackets). Other surface: pixels where the layout's depth let another surface win (normal "
            "more than %.0f° off), left out of the normal and position columns. Picture: against chapter "
            "00's forward renderer at the same cut-off (what the storage alone costs: the agreement tests' "
            "measure), the exact reference (forward, fp32, cut-off 0; up to %d lights, NA beyond) and the "
            "`reference` layout's picture (largest 8-bit difference, pixels more than 1/255 apart). "
            "pbr_teapots has metallic-roughness materials: only the layouts that can hold them "
            "(gbuffer_layout_holds_pbr: reference, whose half-float RT1 keeps the sign that marks them, and "
            "oct16, whose 16-bit RT1 has room for roughness and occlusion beside the normal) draw it; the others "
            "are listed as unable to.\n\n",
            o->width, o->height, o->warmup > 0 ? o->warmup : 1, o->frames, R.pass_clock ? R.pass_clock : "frame",
            OTHER_SURFACE_DEG, o->error_max_lights);
    write_layout_table(f);
    fprintf(f, "| scene | layout | bytes | frame ms | geometry ms | lighting ms | normal max° | "
               "normal mean° |");
    for (int b = 0; b < 3; b++)
        fprintf(f, " position, %s third |", bench_gbuffer_band_names[b]);
    fprintf(f, " other surface |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int si = 0; si < SCENES; si++)
        for (int l = 0; R.scene_done[si] && l < GBUFFER_LAYOUT_COUNT; l++) {
            const layout_row *r = &R.rows[si][l];
            if (!r->measured) {
                fprintf(f, "| %s | %s | – | %s | | | | | | | | |\n", bench_gbuffer_scene_names[si], gbuffer_layout_names[l],
                        r->note);
                continue;
            }
            fprintf(f, "| %s | %s | %d | %.1f | %.1f | %.1f | %.4f | %.4f |", bench_gbuffer_scene_names[si],
                    gbuffer_layout_names[l], gbuffer_layout_bytes(&gbuffer_layouts[l], false), r->frame_ms,
                    r->geometry_ms, r->lighting_ms, r->normal_max, r->normal_mean);
            for (int b = 0; b < 3; b++)
                fprintf(f, " %.2g / %.2g (%.3g) |", r->bands[b].mean, r->bands[b].max, r->bands[b].distance);
            fprintf(f, " %ld |\n", r->other_surface);
        }
    fprintf(f, "\n| scene | layout | vs forward: max 8-bit, pixels > 1 | mean 8-bit | max HDR | mean HDR | "
               "vs exact: mean 8-bit | PSNR 8-bit dB | mean HDR | PSNR HDR dB | vs reference layout: max, "
               "pixels > 1 |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int si = 0; si < SCENES; si++)
        for (int l = 0; R.scene_done[si] && l < GBUFFER_LAYOUT_COUNT; l++) {
            const layout_row *r = &R.rows[si][l];
            if (!r->measured)
                continue;
            fprintf(f, "| %s | %s | %d, %ld | %.4f | %.3g | %.3g |", bench_gbuffer_scene_names[si], gbuffer_layout_names[l],
                    r->vs_forward8.max_abs, r->vs_forward8.over, r->vs_forward8.mean_abs,
                    r->vs_forward_hdr.max_abs, r->vs_forward_hdr.mean_abs);
            if (r->have_exact)
                fprintf(f, " %.4f | %.1f | %.3g | %.1f |", r->error8.mean_abs, r->error8.psnr,
                        r->error_hdr.mean_abs, r->error_hdr.psnr);
            else
                fprintf(f, " NA | NA | NA | NA |");
            fprintf(f, " %d, %ld |\n", r->vs_reference.max_abs, r->vs_reference.over);
        }
    fprintf(f, "\n");
}
