/* test_cone_mesh.c - chapter 09's cone volume must contain the spot's cone cut by its sphere.
 *
 * The lighting pass draws each spot as the template of common/render/light_volumes.c, placed by
 * shaders/cone_volume.glsl (light_volumes_cone_point here, the same formula in double): an apex at the
 * light, a pyramid of 12 faces around the axis, a cap of 3 rings. A face that cuts into the true shape
 * (the cone of the outer angle, cut by the sphere of the light's radius) would lose light along it, as
 * the unscaled icosphere does (tests/unit/test_volume_mesh.c). Checked for outer angles from 0.5 to
 * 89.9 degrees: every face plane against points sampled over the whole boundary of the true shape
 * (which is convex, so its boundary inside means all of it inside) and some inside it; the mesh is
 * closed, convex and wound counter-clockwise seen from outside; and without either scale it cuts in. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "light_volumes.h"
#include "../unit/test_util.h"

#define POLAR_STEPS 200   /* over the cap and along the side: 200 x 400 + 200 x 400 points per angle */
#define AZIMUTH_STEPS 400
/* Everything is computed in double from the same float template: rounding is ~1e-15. */
#define INSIDE_EPSILON 1e-12

static const double OUTER_DEGREES[] = {0.5, 1, 5, 10, 20, 30, 45, 60, 75, 85, 89, 89.9};
#define ANGLE_COUNT (int)(sizeof OUTER_DEGREES / sizeof OUTER_DEGREES[0])

typedef struct cone_volume {
    mesh_data template;
    double (*p)[3];       /* the vertices placed for one angle */
    double (*n)[3], *d;   /* per face: unit normal from the winding, plane dot(n, x) = d */
    int faces;
} cone_volume;

static double deg(double degrees) { return degrees * acos(-1.0) / 180.0; }

static void cone_make(cone_volume *c)
{
    assert_true(light_volumes_cone_mesh_data(&c->template));
    c->faces = c->template.index_count / 3;
    c->p = calloc((size_t)c->template.vertex_count, sizeof *c->p);
    c->n = calloc((size_t)c->faces, sizeof *c->n);
    c->d = calloc((size_t)c->faces, sizeof *c->d);
    assert_true(c->p && c->n && c->d);
}

static void cone_destroy(cone_volume *c)
{
    mesh_data_destroy(&c->template);
    free(c->p), free(c->n), free(c->d);
}

/* The template placed for cos(outer) with the given scales (radius 1, apex at 0, axis +Z). */
static void cone_place(cone_volume *c, double cos_outer, double side_scale, double cap_scale)
{
    for (int v = 0; v < c->template.vertex_count; v++)
        light_volumes_cone_point(c->template.vertices + (size_t)v * MESH_VERTEX_FLOATS, cos_outer, side_scale,
                                 cap_scale, c->p[v]);
    for (int f = 0; f < c->faces; f++) {
        const double *a = c->p[c->template.indices[3 * f]], *b = c->p[c->template.indices[3 * f + 1]],
                     *e = c->p[c->template.indices[3 * f + 2]];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {e[0] - a[0], e[1] - a[1], e[2] - a[2]};
        double *n = c->n[f];
        n[0] = u[1] * w[2] - u[2] * w[1], n[1] = u[2] * w[0] - u[0] * w[2], n[2] = u[0] * w[1] - u[1] * w[0];
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_true(len > 0.0);
        n[0] /= len, n[1] /= len, n[2] /= len;
        c->d[f] = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
    }
}

/* How far x sticks out of the placed mesh: max over faces of dot(n, x) - d; <= 0 is inside. */
static double cone_excess(const cone_volume *c, const double x[3])
{
    double worst = -INFINITY;
    for (int f = 0; f < c->faces; f++)
        worst = fmax(worst, c->n[f][0] * x[0] + c->n[f][1] * x[1] + c->n[f][2] * x[2] - c->d[f]);
    return worst;
}

/* The point at distance r, polar angle `polar` from +Z, azimuth `azimuth`. */
static void spherical(double r, double polar, double azimuth, double out[3])
{
    out[0] = r * sin(polar) * cos(azimuth), out[1] = r * sin(polar) * sin(azimuth), out[2] = r * cos(polar);
}

/* The largest excess over the true shape for outer angle `outer`, per part of it: its cap (distance
 * 1, polar angle up to outer), its side (polar angle outer, distance up to 1; the apex itself lies on
 * every side face, so it is left out: excess 0 there says nothing) and points inside it. */
typedef struct excess {
    double cap, side, inside;
} excess;

static excess shape_excess(const cone_volume *c, double outer)
{
    excess worst = {-INFINITY, -INFINITY, -INFINITY};
    double x[3];
    for (int i = 0; i <= POLAR_STEPS; i++) {
        double s = (double)i / POLAR_STEPS;
        for (int j = 0; j < AZIMUTH_STEPS; j++) {
            double azimuth = 2.0 * acos(-1.0) * (j + 0.5 * (i % 2)) / AZIMUTH_STEPS;
            spherical(1.0, s * outer, azimuth, x);
            worst.cap = fmax(worst.cap, cone_excess(c, x));
            if (i > 0) {
                spherical(s, outer, azimuth, x);
                worst.side = fmax(worst.side, cone_excess(c, x));
            }
            spherical(0.5 * s + 0.25, 0.5 * s * outer, azimuth, x);
            worst.inside = fmax(worst.inside, cone_excess(c, x));
        }
    }
    return worst;
}

static double excess_max(excess e) { return fmax(e.cap, fmax(e.side, e.inside)); }

/* Volume of the placed mesh (closed, outward): the sum of the tetrahedra from the origin. */
static double cone_volume_of(const cone_volume *c)
{
    double v = 0.0;
    for (int f = 0; f < c->faces; f++) {
        const double *a = c->p[c->template.indices[3 * f]], *b = c->p[c->template.indices[3 * f + 1]],
                     *e = c->p[c->template.indices[3 * f + 2]];
        v += (a[0] * (b[1] * e[2] - b[2] * e[1]) - a[1] * (b[0] * e[2] - b[2] * e[0]) +
              a[2] * (b[0] * e[1] - b[1] * e[0])) / 6.0;
    }
    return v;
}

static void test_template(void **state)
{
    (void)state;
    cone_volume c;
    cone_make(&c);
    assert_int_equal(c.template.vertex_count, 2 + LIGHT_VOLUMES_CONE_RINGS * LIGHT_VOLUMES_CONE_SEGMENTS);
    assert_int_equal(c.faces, 2 * LIGHT_VOLUMES_CONE_SEGMENTS * LIGHT_VOLUMES_CONE_RINGS); /* 72 */
    /* Closed and consistently wound: every directed edge once, and its reverse once. */
    int n = c.template.index_count;
    for (int e = 0; e < n; e++) {
        uint32_t a = c.template.indices[e], b = c.template.indices[e % 3 == 2 ? e - 2 : e + 1];
        int same = 0, reverse = 0;
        for (int k = 0; k < n; k++) {
            uint32_t p = c.template.indices[k], q = c.template.indices[k % 3 == 2 ? k - 2 : k + 1];
            same += p == a && q == b;
            reverse += p == b && q == a;
        }
        assert_int_equal(same, 1);
        assert_int_equal(reverse, 1);
    }
    /* The scales: the side's 1 / cos(180 degrees / segments) and the cap's (1.070459 with 12
     * segments and 3 rings), each with its 0.1 % margin. */
    double side = light_volumes_cone_side_scale(), cap = light_volumes_cone_cap_scale(&c.template);
    print_message("side scale %.6f, cap scale %.6f\n", side, cap);
    assert_true(fabs(side - 1.001 / cos(deg(180.0 / LIGHT_VOLUMES_CONE_SEGMENTS))) < 1e-12);
    assert_true(cap > 1.001 && cap < 1.5);
    cone_destroy(&c);
}

/* Convex, outward, and containing the true shape, for every angle; tight (a face touches it). */
static void test_contains_cone(void **state)
{
    (void)state;
    cone_volume c;
    cone_make(&c);
    double side = light_volumes_cone_side_scale(), cap = light_volumes_cone_cap_scale(&c.template);
    for (int k = 0; k < ANGLE_COUNT; k++) {
        double outer = deg(OUTER_DEGREES[k]);
        cone_place(&c, cos(outer), side, cap);
        double centroid[3] = {0};
        for (int v = 0; v < c.template.vertex_count; v++)
            for (int a = 0; a < 3; a++)
                centroid[a] += c.p[v][a] / c.template.vertex_count;
        for (int f = 0; f < c.faces; f++) {
            /* outward: the centroid is behind every face; convex: so is every vertex */
            assert_true(c.n[f][0] * centroid[0] + c.n[f][1] * centroid[1] + c.n[f][2] * centroid[2] < c.d[f]);
            for (int v = 0; v < c.template.vertex_count; v++)
                assert_true(c.n[f][0] * c.p[v][0] + c.n[f][1] * c.p[v][1] + c.n[f][2] * c.p[v][2] - c.d[f] <=
                            1e-9);
        }
        excess e = shape_excess(&c, outer);
        double shape = 2.0 * acos(-1.0) / 3.0 * (1.0 - cos(outer));
        print_message("outer %5.1f deg: worst excess cap %.3g, side %.3g, inside %.3g; "
                      "mesh volume / true volume %.3f\n",
                      OUTER_DEGREES[k], e.cap, e.side, e.inside, cone_volume_of(&c) / shape);
        assert_true(excess_max(e) <= INSIDE_EPSILON);
        /* Tight: the side faces touch the cone (but for the margin); the cap is at most its scale out. */
        assert_true(e.side > -0.002);
        assert_true(e.cap > 1.0 - cap - 1e-9);
    }
    cone_destroy(&c);
}

/* Without the side scale the pyramid's faces cut the cone, without the cap scale the cap's faces cut
 * the sphere: the true shape sticks out, by far more than rounding, at every angle. */
static void test_unscaled_cuts_in(void **state)
{
    (void)state;
    cone_volume c;
    cone_make(&c);
    double side = light_volumes_cone_side_scale(), cap = light_volumes_cone_cap_scale(&c.template);
    for (int k = 0; k < ANGLE_COUNT; k++) {
        double outer = deg(OUTER_DEGREES[k]);
        cone_place(&c, cos(outer), 1.0, cap);
        /* the middle of a side face falls short of the cone by this angle (small near 90 degrees) */
        double short_by = outer - atan(tan(outer) * cos(acos(-1.0) / LIGHT_VOLUMES_CONE_SEGMENTS));
        assert_true(shape_excess(&c, outer).side > 0.5 * sin(short_by));
        cone_place(&c, cos(outer), side, 1.0);
        assert_true(shape_excess(&c, outer).cap > 1e-2 * (1.0 - cos(outer))); /* ~ 1/14 of it measured */
    }
    cone_destroy(&c);
}

/* Tighter than the sphere chapters 04-08 draw for the same light (the icosphere scaled by
 * 1 / inradius), by the ratio of the volumes, for every cone below 90 degrees. */
static void test_tighter_than_sphere(void **state)
{
    (void)state;
    mesh_data ico;
    assert_true(mesh_data_icosphere(&ico, 1));
    double s = 1.0 / mesh_data_inradius(&ico), sphere = 0.0;
    for (int f = 0; f < ico.index_count; f += 3) {
        const float *a = ico.vertices + (size_t)ico.indices[f] * MESH_VERTEX_FLOATS;
        const float *b = ico.vertices + (size_t)ico.indices[f + 1] * MESH_VERTEX_FLOATS;
        const float *e = ico.vertices + (size_t)ico.indices[f + 2] * MESH_VERTEX_FLOATS;
        sphere += s * s * s *
                  ((double)a[0] * ((double)b[1] * e[2] - (double)b[2] * e[1]) -
                   (double)a[1] * ((double)b[0] * e[2] - (double)b[2] * e[0]) +
                   (double)a[2] * ((double)b[0] * e[1] - (double)b[1] * e[0])) / 6.0;
    }
    mesh_data_destroy(&ico);
    cone_volume c;
    cone_make(&c);
    double side = light_volumes_cone_side_scale(), cap = light_volumes_cone_cap_scale(&c.template);
    for (int k = 0; k < ANGLE_COUNT; k++) {
        cone_place(&c, cos(deg(OUTER_DEGREES[k])), side, cap);
        double cone = cone_volume_of(&c);
        print_message("outer %5.1f deg: cone volume %.4f, sphere volume %.4f (%.1fx)\n", OUTER_DEGREES[k], cone,
                      sphere, sphere / cone);
        assert_true(cone < sphere);
    }
    cone_destroy(&c);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_template), cmocka_unit_test(test_contains_cone),
               cmocka_unit_test(test_unscaled_cuts_in), cmocka_unit_test(test_tighter_than_sphere))
