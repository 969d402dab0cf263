/* model_scan.c - model_prescan (model_file.h): every count a model's header declares, checked
 * against the limits and against the bytes that follow it, before Assimp allocates anything. */
#include "model_file.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define PLY_ELEMENTS_MAX 16
#define PLY_PROPERTIES_MAX 64
#define COUNT_DIGITS_MAX 15 /* a count with more digits is refused before it is converted */

/* ---- the pre-scan: counts against limits and bytes --------------------------------------------- */

typedef struct cursor {
    const char *p, *end;
} cursor;

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

/* The next whitespace-separated token; '#' starts a comment to the end of its line when `comments`. */
static bool next_token(cursor *c, bool comments, const char **tok, size_t *len)
{
    for (;;) {
        while (c->p < c->end && is_space(*c->p))
            c->p++;
        if (comments && c->p < c->end && *c->p == '#') {
            while (c->p < c->end && *c->p != '\n')
                c->p++;
            continue;
        }
        break;
    }
    *tok = c->p;
    while (c->p < c->end && !is_space(*c->p))
        c->p++;
    *len = (size_t)(c->p - *tok);
    return *len > 0;
}

static bool parse_count(const char *tok, size_t len, long long *value)
{
    if (len == 0 || len > COUNT_DIGITS_MAX)
        return false;
    long long v = 0;
    for (size_t i = 0; i < len; i++) {
        if (tok[i] < '0' || tok[i] > '9')
            return false;
        v = v * 10 + (tok[i] - '0');
    }
    *value = v;
    return true;
}

static bool check_limits(long long vertices, long long faces, const model_limits *lim, char *why, size_t n)
{
    if (vertices > lim->vertices)
        return model_fail(why, n, "it declares %lld vertices, more than the limit of %ld (COURSE_MODEL_MAX_VERTICES)",
                    vertices, lim->vertices);
    if (faces > lim->faces)
        return model_fail(why, n, "it declares %lld faces, more than the limit of %ld (COURSE_MODEL_MAX_FACES)", faces,
                    lim->faces);
    return true;
}

/* Skips what Assimp 5.2's OFF reader skips between tokens: spaces, line ends and comment lines. */
static const char *off_skip(const char *p, const char *end)
{
    for (;;) {
        while (p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n'))
            p++;
        if (p == end || *p != '#')
            return p;
        while (p < end && *p != '\r' && *p != '\n')
            p++;
    }
}

/* The vertex and face lines as Assimp 5.2 reads them, from just after the face count: the edge
 * count (digits, wherever they are), then one line each, comment lines included. Two of its
 * faults are refused here:
 * - a face line whose corner count is not 1 to 9: it drops that face and takes one off its face
 *   count without reading another line in its place, so enough of them wrap the count past zero
 *   and its validation reads past the face array (valgrind: an invalid read; a crash elsewhere);
 * - a line of 4096 bytes or more: its line buffer is 4096 bytes and it writes the end mark one
 *   past it, on the stack. */
static bool off_check_lines(const char *p, const char *end, long long vertices, long long faces, char *why,
                            size_t n)
{
    p = off_skip(p, end);
    while (p < end && *p >= '0' && *p <= '9')
        p++;
    p = off_skip(p, end);
    for (long long line = 0; line < vertices + faces && p < end; line++) {
        const char *stop = p;
        while (stop < end && *stop != '\r' && *stop != '\n')
            stop++;
        if (stop - p >= 4096)
            return model_fail(why, n, "OFF line %lld after the counts is %td bytes long; Assimp reads at most 4095",
                              line + 1, stop - p);
        if (line >= vertices) {
            const char *q = p;
            while (q < stop && (*q == ' ' || *q == '\t'))
                q++;
            int corners = 0, digits = 0;
            for (; q < stop && *q >= '0' && *q <= '9' && digits < 3; q++, digits++)
                corners = corners * 10 + (*q - '0');
            if (corners < 1 || corners > 9 || (q < stop && *q >= '0' && *q <= '9'))
                return model_fail(why, n, "OFF face %lld does not start with a corner count from 1 to 9 "
                                  "(Assimp 5.2 miscounts its faces on any other)", line - vertices + 1);
        }
        p = stop;
        while (p < end && (*p == '\r' || *p == '\n'))
            p++;
    }
    return true;
}

/* OFF: [ST][C][N][4][n]OFF, then the vertex, face and edge counts; one vertex or face a line. */
static bool prescan_off(const char *d, size_t size, const model_limits *lim, char *why, size_t n)
{
    /* Assimp's reader stops at a NUL byte and splits tokens and lines at a form feed differently
     * from off_check_lines: neither belongs in a text file. */
    for (size_t i = 0; i < size; i++)
        if (d[i] == '\0' || d[i] == '\f' || d[i] == '\v')
            return model_fail(why, n, "byte %zu is a control character (0x%02x), not text", i, (unsigned)d[i]);
    cursor c = {d, d + size};
    const char *tok;
    size_t len;
    if (!next_token(&c, true, &tok, &len))
        return model_fail(why, n, "the file is empty");
    const char *t = tok, *tend = tok + len;
    if (tend - t >= 2 && t[0] == 'S' && t[1] == 'T')
        t += 2;
    bool dimension = false;
    for (const char *flag = "CN4n"; *flag; flag++)
        if (t < tend && *t == *flag)
            t++, dimension = *flag == 'n';
    bool header = tend - t == 3 && memcmp(t, "OFF", 3) == 0;
    if (!header)
        c.p = tok; /* the header is optional: the counts come first */
    else if (dimension && (!next_token(&c, true, &tok, &len) || len != 1 || *tok < '1' || *tok > '3'))
        return model_fail(why, n, "the nOFF header's dimension is not 1, 2 or 3");
    long long counts[2];
    for (int i = 0; i < 2; i++) {
        if (!next_token(&c, true, &tok, &len) || !parse_count(tok, len, &counts[i])) {
            char quoted[40];
            snprintf(quoted, sizeof quoted, "%.*s", (int)(len < 20 ? len : 20), tok);
            model_quote(quoted, quoted, sizeof quoted);
            return model_fail(why, n, "the OFF header's %s count is '%s', not a whole number", i ? "face" : "vertex",
                        quoted);
        }
    }
    if (!check_limits(counts[0], counts[1], lim, why, n))
        return false;
    const char *after_counts = c.p;
    /* Assimp reads a vertex or a face from each line after the counts: the lines must be there. */
    while (c.p < c.end && *c.p != '\n')
        c.p++;
    long long lines = 0;
    while (c.p < c.end) {
        const char *line = ++c.p, *nl = memchr(line, '\n', (size_t)(c.end - line));
        const char *stop = nl ? nl : c.end;
        for (const char *q = line; q < stop && *q != '#'; q++)
            if (!is_space(*q)) {
                lines++;
                break;
            }
        c.p = stop;
    }
    if (lines < counts[0] + counts[1])
        return model_fail(why, n, "its header declares %lld vertices and %lld faces, but %lld lines follow", counts[0],
                    counts[1], lines);
    return off_check_lines(after_counts, d + size, counts[0], counts[1], why, n);
}

typedef struct ply_property {
    int size;      /* bytes of a scalar, or of a list's items */
    int list_size; /* bytes of a list's count; 0 for a scalar */
} ply_property;

typedef struct ply_element {
    char name[32];
    long long count;
    int property_count;
    ply_property properties[PLY_PROPERTIES_MAX];
} ply_element;

static int ply_type_size(const char *tok, size_t len)
{
    static const struct {
        const char *name;
        int size;
    } types[] = {{"char", 1},  {"uchar", 1},  {"int8", 1},  {"uint8", 1},   {"short", 2},   {"ushort", 2},
                 {"int16", 2}, {"uint16", 2}, {"int", 4},   {"uint", 4},    {"int32", 4},   {"uint32", 4},
                 {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strlen(types[i].name) == len && memcmp(types[i].name, tok, len) == 0)
            return types[i].size;
    return 0;
}

static unsigned long long read_uint(const unsigned char *p, int size, bool big)
{
    unsigned long long v = 0;
    for (int i = 0; i < size; i++)
        v |= (unsigned long long)p[big ? size - 1 - i : i] << (8 * i);
    return v;
}

/* A number as Assimp's readers take it: digits, sign, point, exponent, or nan/inf. Assimp 5.2
 * leaks the mesh it was filling (1,320 bytes) when it throws on anything else. */
static bool number_token(const char *tok, size_t len)
{
    char text[65], *end;
    if (len == 0 || len > 64)
        return false;
    memcpy(text, tok, len), text[len] = '\0'; /* the file's bytes end nowhere in particular */
    if (strspn(text, "0123456789+-.eE") < len && strcasecmp(text + (text[0] == '-'), "nan") != 0 &&
        strcasecmp(text + (text[0] == '-'), "inf") != 0)
        return false;
    strtod(text, &end);
    return *end == '\0';
}

/* Walks every element of the body: each list's count must fit in the bytes left, so no count
 * Assimp reads can ask for more memory than the file's size. */
static bool ply_walk(const char *body, size_t size, int format, const ply_element *el, int elements, char *why,
                     size_t n)
{
    cursor c = {body, body + size};
    for (int e = 0; e < elements; e++) {
        for (long long i = 0; i < el[e].count; i++) {
            for (int k = 0; k < el[e].property_count; k++) {
                const ply_property *pr = &el[e].properties[k];
                size_t left = (size_t)(c.end - c.p);
                long long items = 0;
                if (format == 0) {
                    const char *tok;
                    size_t len;
                    if (!next_token(&c, false, &tok, &len))
                        return model_fail(why, n, "the PLY data ends in %s %lld of %lld", el[e].name, i, el[e].count);
                    if (!pr->list_size && !number_token(tok, len))
                        return model_fail(why, n, "PLY %s %lld: a value that is not a number", el[e].name, i);
                    if (!pr->list_size)
                        continue;
                    if (!parse_count(tok, len, &items))
                        return model_fail(why, n, "PLY %s %lld: a list's count is not a whole number", el[e].name, i);
                    if ((unsigned long long)items > left / 2)
                        return model_fail(why, n, "a list in PLY %s %lld holds more items than the file has bytes",
                                    el[e].name, i);
                    for (long long j = 0; j < items; j++) {
                        if (!next_token(&c, false, &tok, &len))
                            return model_fail(why, n, "the PLY data ends in %s %lld of %lld", el[e].name, i, el[e].count);
                        if (!number_token(tok, len))
                            return model_fail(why, n, "PLY %s %lld: a list item that is not a number", el[e].name, i);
                    }
                    continue;
                }
                size_t need = (size_t)(pr->list_size ? pr->list_size : pr->size);
                if (left < need)
                    return model_fail(why, n, "the PLY data ends in %s %lld of %lld", el[e].name, i, el[e].count);
                if (pr->list_size)
                    items = (long long)read_uint((const unsigned char *)c.p, pr->list_size, format == 2);
                c.p += need, left -= need;
                if ((unsigned long long)items > left / (size_t)pr->size)
                    return model_fail(why, n, "a list in PLY %s %lld holds more items than the file has bytes", el[e].name,
                                i);
                c.p += (size_t)items * (size_t)pr->size;
            }
        }
    }
    return true;
}

static bool prescan_ply(const char *d, size_t size, const model_limits *lim, char *why, size_t n)
{
    const char *stop = NULL;
    for (const char *p = d; p + 10 <= d + size; p++)
        if (memcmp(p, "end_header", 10) == 0 && (p == d || p[-1] == '\n')) {
            stop = p;
            break;
        }
    if (size < 3 || memcmp(d, "ply", 3) != 0 || !stop)
        return model_fail(why, n, "no PLY header (a first line 'ply' and an 'end_header' line)");
    const char *after = stop + 10;
    while (after < d + size && (*after == ' ' || *after == '\t' || *after == '\r'))
        after++;
    if (after == d + size || *after != '\n') /* Assimp 5.2 loops for ever on what follows otherwise */
        return model_fail(why, n, "the PLY header's 'end_header' is not alone on its line");
    static ply_element el[PLY_ELEMENTS_MAX]; /* 16 x 64 properties: kept off the stack */
    int elements = 0, format = -1;
    cursor c = {d, stop};
    const char *tok;
    size_t len;
    while (next_token(&c, false, &tok, &len)) {
        const char *line_end = memchr(tok, '\n', (size_t)(stop - tok));
        cursor line = {c.p, line_end ? line_end : stop};
        const char *w[4];
        size_t wl[4];
        int words = 0;
        while (words < 4 && next_token(&line, false, &w[words], &wl[words]))
            words++;
        c.p = line.end;
        if (len == 6 && memcmp(tok, "format", 6) == 0 && words >= 1) {
            format = wl[0] == 5 && memcmp(w[0], "ascii", 5) == 0                  ? 0
                     : wl[0] == 20 && memcmp(w[0], "binary_little_endian", 20) == 0 ? 1
                     : wl[0] == 17 && memcmp(w[0], "binary_big_endian", 17) == 0    ? 2
                                                                                    : -1;
        } else if (len == 7 && memcmp(tok, "element", 7) == 0) {
            if (elements == PLY_ELEMENTS_MAX)
                return model_fail(why, n, "more than %d PLY elements", PLY_ELEMENTS_MAX);
            ply_element *e = &el[elements++];
            memset(e, 0, sizeof *e);
            if (words < 2 || !parse_count(w[1], wl[1], &e->count))
                return model_fail(why, n, "a PLY element line without a whole-number count");
            snprintf(e->name, sizeof e->name, "%.*s", (int)(wl[0] < 31 ? wl[0] : 31), w[0]);
            model_quote(e->name, e->name, sizeof e->name);
        } else if (len == 8 && memcmp(tok, "property", 8) == 0) {
            if (elements == 0 || words < 2)
                return model_fail(why, n, "a PLY property outside an element");
            ply_element *e = &el[elements - 1];
            if (e->property_count == PLY_PROPERTIES_MAX)
                return model_fail(why, n, "more than %d properties in PLY element %s", PLY_PROPERTIES_MAX, e->name);
            ply_property *pr = &e->properties[e->property_count++];
            bool list = wl[0] == 4 && memcmp(w[0], "list", 4) == 0;
            pr->list_size = list && words >= 3 ? ply_type_size(w[1], wl[1]) : 0;
            pr->size = list ? (words >= 3 ? ply_type_size(w[2], wl[2]) : 0) : ply_type_size(w[0], wl[0]);
            if (!pr->size || (list && !pr->list_size))
                return model_fail(why, n, "a PLY property of an unknown type in element %s", e->name);
        }
    }
    if (format < 0)
        return model_fail(why, n, "the PLY format is not ascii, binary_little_endian or binary_big_endian");
    long long vertices = 0, faces = 0;
    bool have_vertices = false;
    int vertex_elements = 0, face_elements = 0;
    for (int i = 0; i < elements; i++) {
        /* Assimp 5.2 sizes its vertex array by the first vertex element and its face array by the
         * first face element, then writes the entries of a later one at their index in those arrays:
         * past the end when the later one is longer (a heap overflow inside Assimp, which
         * AddressSanitizer cannot see: it found it as damage to its own bookkeeping; Assimp's issue
         * 5729, fixed after 5.2). A triangle strip element writes into the same face array, one
         * triangle a strip, leaking the rest. */
        if (strcmp(el[i].name, "tristrips") == 0)
            return model_fail(why, n, "PLY triangle strips (element tristrips) are not read: Assimp 5.2 keeps one "
                                      "triangle of each strip");
        vertex_elements += strcmp(el[i].name, "vertex") == 0;
        face_elements += strcmp(el[i].name, "face") == 0;
        if (vertex_elements > 1 || face_elements > 1)
            return model_fail(why, n, "more than one PLY element %s: Assimp 5.2 writes the second past the end of "
                                      "the array it sized for the first", el[i].name);
        have_vertices |= strcmp(el[i].name, "vertex") == 0 && el[i].count > 0;
        if (el[i].count > 0 && el[i].property_count == 0)
            return model_fail(why, n, "PLY element %s has %lld entries and no property", el[i].name, el[i].count);
        if (strcmp(el[i].name, "vertex") == 0)
            vertices += el[i].count;
        else if (strcmp(el[i].name, "face") == 0)
            faces += el[i].count;
        else if (el[i].count > lim->vertices && el[i].count > lim->faces)
            return model_fail(why, n, "PLY element %s declares %lld entries, more than the vertex and face limits",
                        el[i].name, el[i].count);
    }
    if (!have_vertices)
        return model_fail(why, n, "no PLY vertices (a line 'element vertex N' with N > 0)");
    if (!check_limits(vertices, faces, lim, why, n))
        return false;
    const char *body = memchr(stop, '\n', (size_t)(d + size - stop));
    body = body ? body + 1 : d + size;
    return ply_walk(body, (size_t)(d + size - body), format, el, elements, why, n);
}

/* OBJ: no counts to trust, but its vertex and face lines are counted, and a face needs 3 corners. */
static bool prescan_obj(const char *d, size_t size, const model_limits *lim, char *why, size_t n)
{
    long long vertices = 0, faces = 0, number = 0;
    for (const char *p = d, *end = d + size; p < end;) {
        const char *nl = memchr(p, '\n', (size_t)(end - p)), *stop = nl ? nl : end;
        number++;
        cursor line = {p, stop};
        const char *tok;
        size_t len;
        if (next_token(&line, false, &tok, &len) && len == 1 && (*tok == 'v' || *tok == 'f')) {
            int corners = 0;
            for (const char *t; corners < 3 && next_token(&line, false, &t, &len);)
                corners++;
            if (*tok == 'v')
                vertices++;
            else if (corners < 3)
                return model_fail(why, n, "line %lld: a face needs at least 3 corners, this one has %d", number, corners);
            else
                faces++;
        }
        p = stop + 1;
    }
    return check_limits(vertices, faces, lim, why, n);
}

static bool token_is(const char *tok, size_t len, const char *word)
{
    return strlen(word) == len && memcmp(tok, word, len) == 0;
}

/* A number as Assimp's fast_atof reads it: digits, sign, point, exponent; nothing else. */
static bool stl_number(cursor *c)
{
    const char *tok;
    size_t len;
    return next_token(c, false, &tok, &len) && number_token(tok, len);
}

/* ASCII STL, word by word: Assimp 5.2 leaks the mesh it was filling when it throws on a malformed
 * one (LeakSanitizer: 1,320 and 1,144 bytes), so a malformed file never reaches it. */
static bool prescan_stl_ascii(const char *d, size_t size, const model_limits *lim, char *why, size_t n)
{
    cursor c = {d, d + size};
    const char *tok;
    size_t len;
    long long facets = 0;
    bool open = false;
    while (next_token(&c, false, &tok, &len)) {
        if (token_is(tok, len, "solid") || token_is(tok, len, "endsolid")) {
            if (open == token_is(tok, len, "solid"))
                return model_fail(why, n, "ASCII STL: '%s' %s", token_is(tok, len, "solid") ? "solid" : "endsolid",
                            open ? "inside a solid" : "outside a solid");
            open = !open;
            while (c.p < c.end && *c.p != '\n') /* the solid's name */
                c.p++;
            continue;
        }
        const char *expected = NULL;
        if (!open || !token_is(tok, len, "facet"))
            expected = open ? "facet" : "solid";
        else if (!next_token(&c, false, &tok, &len) || !token_is(tok, len, "normal"))
            expected = "normal";
        else if (!stl_number(&c) || !stl_number(&c) || !stl_number(&c))
            expected = "three numbers after 'normal'";
        else if (!next_token(&c, false, &tok, &len) || !token_is(tok, len, "outer") ||
                 !next_token(&c, false, &tok, &len) || !token_is(tok, len, "loop"))
            expected = "outer loop";
        for (int v = 0; !expected && v < 3; v++)
            if (!next_token(&c, false, &tok, &len) || !token_is(tok, len, "vertex") || !stl_number(&c) ||
                !stl_number(&c) || !stl_number(&c))
                expected = "three 'vertex X Y Z' lines";
        if (!expected && (!next_token(&c, false, &tok, &len) || !token_is(tok, len, "endloop") ||
                          !next_token(&c, false, &tok, &len) || !token_is(tok, len, "endfacet")))
            expected = "endloop and endfacet";
        if (expected)
            return model_fail(why, n, "ASCII STL: expected %s in facet %lld", expected, facets + 1);
        facets++;
    }
    if (open)
        return model_fail(why, n, "ASCII STL: no 'endsolid' at the end");
    return check_limits(0, facets, lim, why, n);
}

static bool prescan_stl(const char *d, size_t size, const model_limits *lim, char *why, size_t n)
{
    /* Binary when the size is exactly 84 + 50 bytes a triangle (Assimp's own test); then the count
     * is already bounded by the size, and only the face limit is left to check. */
    if (size >= 84) {
        unsigned long long count = read_uint((const unsigned char *)d + 80, 4, false);
        if (84 + 50 * count == size)
            return check_limits(0, (long long)count, lim, why, n);
    }
    cursor c = {d, d + size};
    const char *tok;
    size_t len;
    if (!next_token(&c, false, &tok, &len) || !token_is(tok, len, "solid"))
        return model_fail(why, n, "neither a binary STL (84 + 50 bytes a triangle) nor an ASCII one (first word 'solid')");
    return prescan_stl_ascii(d, size, lim, why, n);
}

bool model_prescan(const char *data, size_t size, const char *format, const model_limits *lim, char *why, size_t n)
{
    if ((long long)size > lim->bytes)
        return model_fail(why, n, "%zu bytes, more than the limit of %lld (COURSE_MODEL_MAX_BYTES)", size, lim->bytes);
    if (strcmp(format, "off") == 0)
        return prescan_off(data, size, lim, why, n);
    if (strcmp(format, "ply") == 0)
        return prescan_ply(data, size, lim, why, n);
    if (strcmp(format, "obj") == 0)
        return prescan_obj(data, size, lim, why, n);
    if (strcmp(format, "stl") == 0)
        return prescan_stl(data, size, lim, why, n);
    return true; /* glTF: Assimp checks each accessor against its buffer, whose bytes are limited */
}
