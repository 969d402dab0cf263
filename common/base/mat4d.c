/* mat4d.c - see mat4d.h. */
#include "mat4d.h"

/* Element (row, col) of a column-major 4x4 matrix. */
#define AT(m, row, col) (m)[4 * (col) + (row)]

void mat4d_from_float(const float m[16], double out[16])
{
    for (int i = 0; i < 16; i++)
        out[i] = m[i];
}

/* The three of 0..3 other than `skip`, in order. */
static void others(int skip, int out[3])
{
    for (int i = 0, n = 0; i < 4; i++)
        if (i != skip)
            out[n++] = i;
}

/* Cofactor of m(row, col): the 3x3 determinant left when that row and column are struck out, expanded
 * along its first row, each product and sum in the order of the classic unrolled inverse (the
 * G-buffer's reversed-Z matrix and the ideal light work keep their exact bits). */
static double cofactor(const double m[16], int row, int col)
{
    int r[3], c[3];
    others(row, r);
    others(col, c);
    double sum = 0.0;
    for (int n = 0; n < 3; n++) {
        const int p = c[n == 0 ? 1 : 0], q = c[n == 2 ? 1 : 2]; /* the other two columns */
        const double f = ((row + col + n) % 2 ? -1.0 : 1.0) * AT(m, r[0], c[n]);
        const double first = f * AT(m, r[1], p) * AT(m, r[2], q),
                     second = f * AT(m, r[2], p) * AT(m, r[1], q);
        sum = n == 0 ? first - second : sum + first - second;
    }
    return sum;
}

bool mat4d_invert(const double m[16], double out[16])
{
    double adj[16]; /* adj(j, i) is the cofactor of m(i, j) */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            AT(adj, j, i) = cofactor(m, i, j);
    const double det = m[0] * adj[0] + m[1] * adj[4] + m[2] * adj[8] + m[3] * adj[12]; /* along column 0 */
    for (int i = 0; i < 16; i++)
        out[i] = adj[i] / det;
    return det != 0.0;
}
