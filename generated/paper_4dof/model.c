/* GENERATED FILE: DO NOT EDIT.
 * Regenerate: `jointplay derive robot.toml --out <this folder>`, or for the models
 * checked in under generated/: `pytest tests/test_generated.py --update-generated`.
 * model: paper_4dof
 * generator: jointplay.derive 1, casadi 3.8.2, sympy 1.14.0
 * input hash: 8bb0bc0d0c448ab7c2b890651e7c7a1fb8313f2803584fdc1e03e6d2bde1fd0f
 * Every input and output slot is described, with names and units, in layout.json.
 * Functions (inputs -> outputs; column vectors, dense, float64):
 *   mass_matrix(q[6], p[39]) -> M[6x6]
 *   forcing(x[12], tau[2], p[39], v_imp[2]) -> f[6x1]
 *   forward_dynamics(x[12], tau[2], p[39], v_imp[2]) -> xdot[12x1]
 *   jac_forward_dynamics: d forward_dynamics / d each input, CasADi's calling convention
 *   contact(x[12], p[39], v_imp[2]) -> delta[2x1], delta_dot[2x1], v_t[2x1], f_n[2x1], f_t[2x1], f_x[2x1], f_y[2x1]
 *   energy(x[12], p[39]) -> kinetic[1x1], gravity[1x1], contact[1x1], total[1x1]
 *   end_effector(x[12], udot[6], p[39]) -> position[2x1], velocity[2x1], acceleration[2x1]
 * x [rad, m, rad/s, m/s]: state: coordinates then their time derivatives
 *     0: q2, q3, ex2, ey2, ex3, ey3
 *     6: dq2, dq3, dex2, dey2, dex3, dey3
 * tau [N m]: drive torque of each moving joint (on link i, reaction on link i-1)
 *     0: tau2, tau3
 * p [SI]: parameter vector (see 'parameters')
 *     0: link1.length, link1.mass, link1.inertia, link1.com, link2.length, link2.mass
 *     6: link2.inertia, link2.com, link3.length, link3.mass, link3.inertia, link3.com
 *     12: link4.length, link4.mass, link4.inertia, link4.com, payload.mass, gravity.x
 *     18: gravity.y, joint1.angle, joint2.bearing_radius, joint2.journal_radius, joint2.bearing_E, joint2.bearing_nu
 *     24: joint2.journal_E, joint2.journal_nu, joint3.bearing_radius, joint3.journal_radius, joint3.bearing_E, joint3.bearing_nu
 *     30: joint3.journal_E, joint3.journal_nu, joint4.angle, contact.exponent, contact.restitution, contact.impact_speed_floor
 *     36: friction.mu, friction.v0, friction.v1
 * v_imp [m/s]: normal approach speed captured at the onset of each joint's current impact
 *     0: v_imp2, v_imp3
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) model_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_clear CASADI_PREFIX(clear)
#define casadi_copy CASADI_PREFIX(copy)
#define casadi_densify CASADI_PREFIX(densify)
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_f1 CASADI_PREFIX(f1)
#define casadi_f2 CASADI_PREFIX(f2)
#define casadi_f3 CASADI_PREFIX(f3)
#define casadi_f4 CASADI_PREFIX(f4)
#define casadi_f5 CASADI_PREFIX(f5)
#define casadi_f6 CASADI_PREFIX(f6)
#define casadi_f7 CASADI_PREFIX(f7)
#define casadi_fabs CASADI_PREFIX(fabs)
#define casadi_fill CASADI_PREFIX(fill)
#define casadi_fmax CASADI_PREFIX(fmax)
#define casadi_fmin CASADI_PREFIX(fmin)
#define casadi_ldl CASADI_PREFIX(ldl)
#define casadi_ldl_solve CASADI_PREFIX(ldl_solve)
#define casadi_ldl_trs CASADI_PREFIX(ldl_trs)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s10 CASADI_PREFIX(s10)
#define casadi_s11 CASADI_PREFIX(s11)
#define casadi_s12 CASADI_PREFIX(s12)
#define casadi_s13 CASADI_PREFIX(s13)
#define casadi_s14 CASADI_PREFIX(s14)
#define casadi_s15 CASADI_PREFIX(s15)
#define casadi_s16 CASADI_PREFIX(s16)
#define casadi_s17 CASADI_PREFIX(s17)
#define casadi_s18 CASADI_PREFIX(s18)
#define casadi_s19 CASADI_PREFIX(s19)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_s8 CASADI_PREFIX(s8)
#define casadi_s9 CASADI_PREFIX(s9)
#define casadi_sign CASADI_PREFIX(sign)
#define casadi_sq CASADI_PREFIX(sq)
#define casadi_trans CASADI_PREFIX(trans)
#define casadi_zeros CASADI_PREFIX(zeros)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

casadi_real casadi_fmax(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x>y ? x : y;
#else
  return fmax(x, y);
#endif
}

casadi_real casadi_fabs(casadi_real x) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x>0 ? x : -x;
#else
  return fabs(x);
#endif
}

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return fmin(x, y);
#endif
}

void casadi_copy(const casadi_real* x, casadi_int n, casadi_real* y) {
  casadi_int i;
  if (y) {
    if (x) {
      for (i=0; i<n; ++i) *y++ = *x++;
    } else {
      for (i=0; i<n; ++i) *y++ = 0.;
    }
  }
}

void casadi_ldl(const casadi_int* sp_a, const casadi_real* a,
                const casadi_int* sp_lt, casadi_real* lt, casadi_real* d, const casadi_int* p, casadi_real* w) {
  const casadi_int *lt_colind, *lt_row, *a_colind, *a_row;
  casadi_int n, r, c, c1, k, k2;
  n=sp_lt[1];
  lt_colind=sp_lt+2; lt_row=sp_lt+2+n+1;
  a_colind=sp_a+2; a_row=sp_a+2+n+1;
  for (r=0; r<n; ++r) w[r] = 0;
  for (c=0; c<n; ++c) {
    c1 = p[c];
    for (k=a_colind[c1]; k<a_colind[c1+1]; ++k) w[a_row[k]] = a[k];
    for (k=lt_colind[c]; k<lt_colind[c+1]; ++k) lt[k] = w[p[lt_row[k]]];
    d[c] = w[p[c]];
    for (k=a_colind[c1]; k<a_colind[c1+1]; ++k) w[a_row[k]] = 0;
  }
  for (c=0; c<n; ++c) {
    for (k=lt_colind[c]; k<lt_colind[c+1]; ++k) {
      r = lt_row[k];
      for (k2=lt_colind[r]; k2<lt_colind[r+1]; ++k2) {
        lt[k] -= lt[k2] * w[lt_row[k2]];
      }
      w[r] = lt[k];
      lt[k] /= d[r];
      d[c] -= w[r]*lt[k];
    }
    for (k=lt_colind[c]; k<lt_colind[c+1]; ++k) w[lt_row[k]] = 0;
  }
}
void casadi_ldl_trs(const casadi_int* sp_r, const casadi_real* nz_r, casadi_real* x, casadi_int tr) {
  casadi_int ncol, c, k;
  const casadi_int *colind, *row;
  ncol=sp_r[1];
  colind=sp_r+2; row=sp_r+2+ncol+1;
  if (tr) {
    for (c=0; c<ncol; ++c) {
      for (k=colind[c]; k<colind[c+1]; ++k) {
        x[c] -= nz_r[k]*x[row[k]];
      }
    }
  } else {
    for (c=ncol-1; c>=0; --c) {
      for (k=colind[c+1]-1; k>=colind[c]; --k) {
        x[row[k]] -= nz_r[k]*x[c];
      }
    }
  }
}
void casadi_ldl_solve(casadi_real* x, casadi_int nrhs, const casadi_int* sp_lt, const casadi_real* lt,
                      const casadi_real* d, const casadi_int* p, casadi_real* w) {
  casadi_int i, k;
  casadi_int n = sp_lt[1];
  for (k=0; k<nrhs; ++k) {
    for (i=0; i<n; ++i) w[i] = x[p[i]];
    casadi_ldl_trs(sp_lt, lt, w, 1);
    for (i=0; i<n; ++i) w[i] /= d[i];
    casadi_ldl_trs(sp_lt, lt, w, 0);
    for (i=0; i<n; ++i) x[p[i]] = w[i];
    x += n;
  }
}

casadi_real casadi_sign(casadi_real x) { return x<0 ? -1 : x>0 ? 1 : x;}

void casadi_clear(casadi_real* x, casadi_int n) {
  casadi_int i;
  if (x) {
    for (i=0; i<n; ++i) *x++ = 0;
  }
}

void casadi_fill(casadi_real* x, casadi_int n, casadi_real alpha) {
  casadi_int i;
  if (x) {
    for (i=0; i<n; ++i) *x++ = alpha;
  }
}

#define CASADI_CAST(x,y) ((x) y)

void casadi_densify(const casadi_real* x, const casadi_int* sp_x, casadi_real* y, casadi_int tr) {
  casadi_int nrow_x, ncol_x, i, el;
  const casadi_int *colind_x, *row_x;
  if (!y) return;
  nrow_x = sp_x[0]; ncol_x = sp_x[1];
  colind_x = sp_x+2; row_x = sp_x+ncol_x+3;
  casadi_clear(y, nrow_x*ncol_x);
  if (!x) return;
  if (tr) {
    for (i=0; i<ncol_x; ++i) {
      for (el=colind_x[i]; el!=colind_x[i+1]; ++el) {
        y[i + row_x[el]*ncol_x] = CASADI_CAST(casadi_real, *x++);
      }
    }
  } else {
    for (i=0; i<ncol_x; ++i) {
      for (el=colind_x[i]; el!=colind_x[i+1]; ++el) {
        y[row_x[el]] = CASADI_CAST(casadi_real, *x++);
      }
      y += nrow_x;
    }
  }
}

void casadi_trans(const casadi_real* x, const casadi_int* sp_x, casadi_real* y,
    const casadi_int* sp_y, casadi_int* tmp) {
  casadi_int ncol_x, nnz_x, ncol_y, k;
  const casadi_int* row_x, *colind_y;
  ncol_x = sp_x[1];
  nnz_x = sp_x[2 + ncol_x];
  row_x = sp_x + 2 + ncol_x+1;
  ncol_y = sp_y[1];
  colind_y = sp_y+2;
  for (k=0; k<ncol_y; ++k) tmp[k] = colind_y[k];
  for (k=0; k<nnz_x; ++k) {
    y[tmp[row_x[k]]++] = x[k];
  }
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void model_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int model_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int model_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {39, 1, 1};
static const casadi_int casadi_s2[3] = {6, 6, 1};
static const casadi_int casadi_s3[3] = {12, 1, 1};
static const casadi_int casadi_s4[3] = {2, 1, 1};
static const casadi_int casadi_s5[45] = 
  {6, 6, 0, 6, 12, 18, 24, 30,
  36, 0, 1, 2, 3, 4, 5, 0,
  1, 2, 3, 4, 5, 0, 1, 2,
  3, 4, 5, 0, 1, 2, 3, 4,
  5, 0, 1, 2, 3, 4, 5, 0,
  1, 2, 3, 4, 5};
static const casadi_int casadi_s6[24] = 
  {6, 6, 0, 0, 1, 3, 6, 10,
  15, 0, 0, 1, 0, 1, 2, 0,
  1, 2, 3, 0, 1, 2, 3, 4};
static const casadi_int casadi_s7[6] = {0, 1, 2, 3, 4, 5};
static const casadi_int casadi_s8[67] = 
  {6, 12, 0, 6, 12, 15, 18, 22,
  26, 32, 38, 41, 44, 48, 52, 0,
  1, 2, 3, 4, 5, 0, 1, 2,
  3, 4, 5, 0, 2, 3, 0, 2,
  3, 0, 1, 4, 5, 0, 1, 4,
  5, 0, 1, 2, 3, 4, 5, 0,
  1, 2, 3, 4, 5, 0, 2, 3,
  0, 2, 3, 0, 1, 4, 5, 0,
  1, 4, 5};
static const casadi_int casadi_s9[93] = 
  {12, 12, 0, 6, 12, 18, 24, 30,
  36, 43, 50, 57, 64, 71, 78, 6,
  7, 8, 9, 10, 11, 6, 7, 8,
  9, 10, 11, 6, 7, 8, 9, 10,
  11, 6, 7, 8, 9, 10, 11, 6,
  7, 8, 9, 10, 11, 6, 7, 8,
  9, 10, 11, 0, 6, 7, 8, 9,
  10, 11, 1, 6, 7, 8, 9, 10,
  11, 2, 6, 7, 8, 9, 10, 11,
  3, 6, 7, 8, 9, 10, 11, 4,
  6, 7, 8, 9, 10, 11, 5, 6,
  7, 8, 9, 10, 11};
static const casadi_int casadi_s10[93] = 
  {12, 12, 0, 1, 2, 3, 4, 5,
  6, 18, 30, 42, 54, 66, 78, 6,
  7, 8, 9, 10, 11, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11};
static const casadi_int casadi_s11[7] = {6, 2, 0, 1, 2, 0, 1};
static const casadi_int casadi_s12[17] = 
  {12, 2, 0, 6, 12, 6, 7, 8,
  9, 10, 11, 6, 7, 8, 9, 10,
  11};
static const casadi_int casadi_s13[27] = 
  {2, 12, 0, 0, 0, 0, 0, 0,
  0, 2, 4, 6, 8, 10, 12, 0,
  1, 0, 1, 0, 1, 0, 1, 0,
  1, 0, 1};
static const casadi_int casadi_s14[199] = 
  {6, 39, 0, 0, 0, 0, 0, 6,
  9, 10, 13, 19, 25, 27, 33, 39,
  45, 47, 53, 59, 63, 67, 73, 76,
  79, 82, 85, 88, 91, 95, 99, 103,
  107, 111, 115, 121, 127, 133, 139, 145,
  151, 157, 0, 1, 2, 3, 4, 5,
  0, 2, 3, 0, 0, 2, 3, 0,
  1, 2, 3, 4, 5, 0, 1, 2,
  3, 4, 5, 0, 1, 0, 1, 2,
  3, 4, 5, 0, 1, 2, 3, 4,
  5, 0, 1, 2, 3, 4, 5, 0,
  1, 0, 1, 2, 3, 4, 5, 0,
  1, 2, 3, 4, 5, 0, 1, 2,
  4, 0, 1, 3, 5, 0, 1, 2,
  3, 4, 5, 0, 2, 3, 0, 2,
  3, 0, 2, 3, 0, 2, 3, 0,
  2, 3, 0, 2, 3, 0, 1, 4,
  5, 0, 1, 4, 5, 0, 1, 4,
  5, 0, 1, 4, 5, 0, 1, 4,
  5, 0, 1, 4, 5, 0, 1, 2,
  3, 4, 5, 0, 1, 2, 3, 4,
  5, 0, 1, 2, 3, 4, 5, 0,
  1, 2, 3, 4, 5, 0, 1, 2,
  3, 4, 5, 0, 1, 2, 3, 4,
  5, 0, 1, 2, 3, 4, 5};
static const casadi_int casadi_s15[276] = 
  {12, 39, 0, 6, 12, 18, 24, 30,
  36, 42, 48, 54, 60, 66, 72, 78,
  84, 90, 96, 102, 108, 114, 120, 126,
  132, 138, 144, 150, 156, 162, 168, 174,
  180, 186, 192, 198, 204, 210, 216, 222,
  228, 234, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11, 6, 7, 8, 9,
  10, 11, 6, 7, 8, 9, 10, 11,
  6, 7, 8, 9, 10, 11, 6, 7,
  8, 9, 10, 11};
static const casadi_int casadi_s16[249] = 
  {39, 12, 0, 0, 0, 0, 0, 0,
  0, 39, 78, 117, 156, 195, 234, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 18, 19, 20, 21, 22, 23, 24,
  25, 26, 27, 28, 29, 30, 31, 32,
  33, 34, 35, 36, 37, 38, 0, 1,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 11, 12, 13, 14, 15, 16, 17,
  18, 19, 20, 21, 22, 23, 24, 25,
  26, 27, 28, 29, 30, 31, 32, 33,
  34, 35, 36, 37, 38, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 18,
  19, 20, 21, 22, 23, 24, 25, 26,
  27, 28, 29, 30, 31, 32, 33, 34,
  35, 36, 37, 38, 0, 1, 2, 3,
  4, 5, 6, 7, 8, 9, 10, 11,
  12, 13, 14, 15, 16, 17, 18, 19,
  20, 21, 22, 23, 24, 25, 26, 27,
  28, 29, 30, 31, 32, 33, 34, 35,
  36, 37, 38, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 18, 19, 20,
  21, 22, 23, 24, 25, 26, 27, 28,
  29, 30, 31, 32, 33, 34, 35, 36,
  37, 38, 0, 1, 2, 3, 4, 5,
  6, 7, 8, 9, 10, 11, 12, 13,
  14, 15, 16, 17, 18, 19, 20, 21,
  22, 23, 24, 25, 26, 27, 28, 29,
  30, 31, 32, 33, 34, 35, 36, 37,
  38};
static const casadi_int casadi_s17[12] = 
  {6, 2, 0, 3, 7, 0, 2, 3,
  0, 1, 4, 5};
static const casadi_int casadi_s18[4] = {12, 1, 0, 0};
static const casadi_int casadi_s19[3] = {1, 1, 1};

static const casadi_real casadi_zeros[39] = 
  {0.};

/* mass_matrix:(q[6],p[39])->(M[6x6]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26;
  a00=arg[1]? arg[1][6] : 0;
  a01=arg[1]? arg[1][10] : 0;
  a00=(a00+a01);
  a02=arg[1]? arg[1][14] : 0;
  a00=(a00+a02);
  a03=arg[1]? arg[1][5] : 0;
  a04=arg[1]? arg[1][7] : 0;
  a05=casadi_sq(a04);
  a05=(a03*a05);
  a00=(a00+a05);
  a05=arg[1]? arg[1][9] : 0;
  a06=arg[1]? arg[1][4] : 0;
  a07=arg[1]? arg[1][19] : 0;
  a08=arg[0]? arg[0][0] : 0;
  a09=(a07+a08);
  a10=cos(a09);
  a11=(a06*a10);
  a12=arg[1]? arg[1][11] : 0;
  a13=(a07+a08);
  a14=arg[0]? arg[0][1] : 0;
  a13=(a13+a14);
  a15=cos(a13);
  a16=(a12*a15);
  a16=(a11+a16);
  a17=casadi_sq(a16);
  a09=sin(a09);
  a06=(a06*a09);
  a13=sin(a13);
  a18=(a12*a13);
  a18=(a06+a18);
  a19=casadi_sq(a18);
  a17=(a17+a19);
  a17=(a05*a17);
  a00=(a00+a17);
  a17=arg[1]? arg[1][13] : 0;
  a19=arg[1]? arg[1][8] : 0;
  a20=(a19*a15);
  a21=(a11+a20);
  a22=arg[1]? arg[1][15] : 0;
  a23=arg[1]? arg[1][32] : 0;
  a07=(a07+a23);
  a07=(a07+a08);
  a07=(a07+a14);
  a14=cos(a07);
  a08=(a22*a14);
  a21=(a21+a08);
  a23=casadi_sq(a21);
  a19=(a19*a13);
  a24=(a06+a19);
  a07=sin(a07);
  a22=(a22*a07);
  a24=(a24+a22);
  a25=casadi_sq(a24);
  a23=(a23+a25);
  a23=(a17*a23);
  a00=(a00+a23);
  a23=arg[1]? arg[1][16] : 0;
  a11=(a11+a20);
  a25=arg[1]? arg[1][12] : 0;
  a14=(a25*a14);
  a11=(a11+a14);
  a26=casadi_sq(a11);
  a06=(a06+a19);
  a25=(a25*a07);
  a06=(a06+a25);
  a07=casadi_sq(a06);
  a26=(a26+a07);
  a26=(a23*a26);
  a00=(a00+a26);
  if (res[0]!=0) res[0][0]=a00;
  a00=(a01+a02);
  a26=(a12*a16);
  a26=(a26*a15);
  a07=(a12*a18);
  a07=(a07*a13);
  a26=(a26+a07);
  a26=(a05*a26);
  a00=(a00+a26);
  a08=(a20+a08);
  a26=(a08*a21);
  a22=(a19+a22);
  a07=(a22*a24);
  a26=(a26+a07);
  a26=(a17*a26);
  a00=(a00+a26);
  a20=(a20+a14);
  a14=(a20*a11);
  a19=(a19+a25);
  a25=(a19*a06);
  a14=(a14+a25);
  a14=(a23*a14);
  a00=(a00+a14);
  if (res[0]!=0) res[0][1]=a00;
  a18=(a05*a18);
  a24=(a17*a24);
  a14=(a18+a24);
  a06=(a23*a06);
  a14=(a14+a06);
  a25=(a04*a03);
  a25=(a25*a09);
  a14=(a14+a25);
  a14=(-a14);
  if (res[0]!=0) res[0][2]=a14;
  a16=(a05*a16);
  a21=(a17*a21);
  a25=(a16+a21);
  a11=(a23*a11);
  a25=(a25+a11);
  a04=(a04*a03);
  a04=(a04*a10);
  a25=(a25+a04);
  if (res[0]!=0) res[0][3]=a25;
  a18=(a18+a24);
  a18=(a18+a06);
  a18=(-a18);
  if (res[0]!=0) res[0][4]=a18;
  a16=(a16+a21);
  a16=(a16+a11);
  if (res[0]!=0) res[0][5]=a16;
  if (res[0]!=0) res[0][6]=a00;
  a01=(a01+a02);
  a02=casadi_sq(a12);
  a02=(a05*a02);
  a01=(a01+a02);
  a02=casadi_sq(a08);
  a00=casadi_sq(a22);
  a02=(a02+a00);
  a02=(a17*a02);
  a01=(a01+a02);
  a02=casadi_sq(a20);
  a00=casadi_sq(a19);
  a02=(a02+a00);
  a02=(a23*a02);
  a01=(a01+a02);
  if (res[0]!=0) res[0][7]=a01;
  a22=(a17*a22);
  a19=(a23*a19);
  a22=(a22+a19);
  a19=(a12*a05);
  a19=(a19*a13);
  a22=(a22+a19);
  a22=(-a22);
  if (res[0]!=0) res[0][8]=a22;
  a08=(a17*a08);
  a20=(a23*a20);
  a08=(a08+a20);
  a12=(a12*a05);
  a12=(a12*a15);
  a08=(a08+a12);
  if (res[0]!=0) res[0][9]=a08;
  if (res[0]!=0) res[0][10]=a22;
  if (res[0]!=0) res[0][11]=a08;
  if (res[0]!=0) res[0][12]=a14;
  if (res[0]!=0) res[0][13]=a22;
  a03=(a03+a05);
  a03=(a03+a17);
  a03=(a03+a23);
  if (res[0]!=0) res[0][14]=a03;
  a14=0.;
  if (res[0]!=0) res[0][15]=a14;
  a05=(a05+a17);
  a05=(a05+a23);
  if (res[0]!=0) res[0][16]=a05;
  if (res[0]!=0) res[0][17]=a14;
  if (res[0]!=0) res[0][18]=a25;
  if (res[0]!=0) res[0][19]=a08;
  if (res[0]!=0) res[0][20]=a14;
  if (res[0]!=0) res[0][21]=a03;
  if (res[0]!=0) res[0][22]=a14;
  if (res[0]!=0) res[0][23]=a05;
  if (res[0]!=0) res[0][24]=a18;
  if (res[0]!=0) res[0][25]=a22;
  if (res[0]!=0) res[0][26]=a05;
  if (res[0]!=0) res[0][27]=a14;
  if (res[0]!=0) res[0][28]=a05;
  if (res[0]!=0) res[0][29]=a14;
  if (res[0]!=0) res[0][30]=a16;
  if (res[0]!=0) res[0][31]=a08;
  if (res[0]!=0) res[0][32]=a14;
  if (res[0]!=0) res[0][33]=a05;
  if (res[0]!=0) res[0][34]=a14;
  if (res[0]!=0) res[0][35]=a05;
  return 0;
}

CASADI_SYMBOL_EXPORT int mass_matrix(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int mass_matrix_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void mass_matrix_release(int mem) {
}

CASADI_SYMBOL_EXPORT void mass_matrix_incref(void) {
}

CASADI_SYMBOL_EXPORT void mass_matrix_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int mass_matrix_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int mass_matrix_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real mass_matrix_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* mass_matrix_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "p";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* mass_matrix_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* mass_matrix_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* mass_matrix_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int mass_matrix_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int mass_matrix_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* forcing:(x[12],tau[2],p[39],v_imp[2])->(f[6]) */
static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50;
  a00=arg[1]? arg[1][0] : 0;
  a01=arg[2]? arg[2][36] : 0;
  a02=arg[2]? arg[2][37] : 0;
  a03=arg[2]? arg[2][21] : 0;
  a04=arg[0]? arg[0][6] : 0;
  a05=(a03*a04);
  a06=-9.9999999999999995e-07;
  a07=(a06*a03);
  a08=9.9999999999999995e-07;
  a09=arg[2]? arg[2][20] : 0;
  a10=(a08*a09);
  a07=(a07+a10);
  a07=casadi_sq(a07);
  a10=arg[0]? arg[0][2] : 0;
  a11=casadi_sq(a10);
  a12=arg[0]? arg[0][3] : 0;
  a13=casadi_sq(a12);
  a11=(a11+a13);
  a07=casadi_fmax(a07,a11);
  a11=-5.0000000000000000e-01;
  a13=pow(a07,a11);
  a14=(a13*a10);
  a15=arg[0]? arg[0][9] : 0;
  a14=(a14*a15);
  a05=(a05+a14);
  a14=(a13*a12);
  a16=arg[0]? arg[0][8] : 0;
  a14=(a14*a16);
  a05=(a05-a14);
  a14=casadi_fabs(a05);
  a17=casadi_fmax(a02,a14);
  a18=(a01/a17);
  a18=(a18*a05);
  a19=0.;
  a20=1.3333333333333333e+00;
  a21=(a09*a03);
  a22=(a09-a03);
  a21=(a21/a22);
  a21=sqrt(a21);
  a21=(a20*a21);
  a22=1.;
  a23=arg[2]? arg[2][23] : 0;
  a23=casadi_sq(a23);
  a23=(a22-a23);
  a24=arg[2]? arg[2][22] : 0;
  a23=(a23/a24);
  a24=arg[2]? arg[2][25] : 0;
  a24=casadi_sq(a24);
  a24=(a22-a24);
  a25=arg[2]? arg[2][24] : 0;
  a24=(a24/a25);
  a23=(a23+a24);
  a21=(a21/a23);
  a07=sqrt(a07);
  a07=(a03+a07);
  a07=(a07-a09);
  a07=casadi_fmax(a19,a07);
  a09=arg[2]? arg[2][33] : 0;
  a07=pow(a07,a09);
  a21=(a21*a07);
  a07=7.5000000000000000e-01;
  a23=-7.5000000000000000e-01;
  a24=arg[2]? arg[2][34] : 0;
  a24=casadi_sq(a24);
  a23=(a23*a24);
  a07=(a07+a23);
  a23=arg[3]? arg[3][0] : 0;
  a24=arg[2]? arg[2][35] : 0;
  a23=casadi_fmax(a23,a24);
  a23=(a07/a23);
  a25=(a13*a10);
  a25=(a25*a16);
  a16=(a13*a12);
  a16=(a16*a15);
  a25=(a25+a16);
  a23=(a23*a25);
  a23=(a22+a23);
  a21=(a21*a23);
  a21=casadi_fmax(a19,a21);
  a18=(a18*a21);
  a14=(a14-a02);
  a23=arg[2]? arg[2][38] : 0;
  a23=(a23-a02);
  a14=(a14/a23);
  a14=casadi_fmax(a19,a14);
  a14=casadi_fmin(a22,a14);
  a18=(a18*a14);
  a18=(a18*a03);
  a00=(a00-a18);
  a18=arg[2]? arg[2][26] : 0;
  a03=(a18*a04);
  a25=arg[2]? arg[2][27] : 0;
  a16=arg[0]? arg[0][7] : 0;
  a16=(a04+a16);
  a15=(a25*a16);
  a03=(a03-a15);
  a06=(a06*a25);
  a08=(a08*a18);
  a06=(a06+a08);
  a06=casadi_sq(a06);
  a08=arg[0]? arg[0][4] : 0;
  a15=casadi_sq(a08);
  a26=arg[0]? arg[0][5] : 0;
  a27=casadi_sq(a26);
  a15=(a15+a27);
  a06=casadi_fmax(a06,a15);
  a11=pow(a06,a11);
  a15=(a11*a26);
  a27=arg[0]? arg[0][10] : 0;
  a15=(a15*a27);
  a03=(a03+a15);
  a15=(a11*a08);
  a28=arg[0]? arg[0][11] : 0;
  a15=(a15*a28);
  a03=(a03-a15);
  a03=casadi_fabs(a03);
  a15=casadi_fmax(a02,a03);
  a29=(a01/a15);
  a30=(a25*a16);
  a31=(a18*a04);
  a30=(a30-a31);
  a31=(a11*a08);
  a31=(a31*a28);
  a30=(a30+a31);
  a31=(a11*a26);
  a31=(a31*a27);
  a30=(a30-a31);
  a29=(a29*a30);
  a31=(a18*a25);
  a32=(a18-a25);
  a31=(a31/a32);
  a31=sqrt(a31);
  a20=(a20*a31);
  a31=arg[2]? arg[2][29] : 0;
  a31=casadi_sq(a31);
  a31=(a22-a31);
  a32=arg[2]? arg[2][28] : 0;
  a31=(a31/a32);
  a32=arg[2]? arg[2][31] : 0;
  a32=casadi_sq(a32);
  a32=(a22-a32);
  a33=arg[2]? arg[2][30] : 0;
  a32=(a32/a33);
  a31=(a31+a32);
  a20=(a20/a31);
  a06=sqrt(a06);
  a06=(a25+a06);
  a06=(a06-a18);
  a06=casadi_fmax(a19,a06);
  a06=pow(a06,a09);
  a20=(a20*a06);
  a06=arg[3]? arg[3][1] : 0;
  a06=casadi_fmax(a06,a24);
  a07=(a07/a06);
  a06=(a11*a08);
  a06=(a06*a27);
  a27=(a11*a26);
  a27=(a27*a28);
  a06=(a06+a27);
  a07=(a07*a06);
  a07=(a22+a07);
  a20=(a20*a07);
  a20=casadi_fmax(a19,a20);
  a29=(a29*a20);
  a03=(a03-a02);
  a03=(a03/a23);
  a19=casadi_fmax(a19,a03);
  a22=casadi_fmin(a22,a19);
  a29=(a29*a22);
  a25=(a29*a25);
  a00=(a00-a25);
  a29=(a29*a18);
  a00=(a00+a29);
  a29=arg[2]? arg[2][17] : 0;
  a18=arg[2]? arg[2][9] : 0;
  a19=(a29*a18);
  a03=arg[2]? arg[2][4] : 0;
  a23=arg[2]? arg[2][19] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a07=(a23+a02);
  a06=sin(a07);
  a27=(a03*a06);
  a28=arg[2]? arg[2][11] : 0;
  a24=(a23+a02);
  a09=arg[0]? arg[0][1] : 0;
  a24=(a24+a09);
  a31=sin(a24);
  a32=(a28*a31);
  a32=(a27+a32);
  a19=(a19*a32);
  a00=(a00-a19);
  a19=arg[2]? arg[2][13] : 0;
  a33=(a29*a19);
  a34=arg[2]? arg[2][8] : 0;
  a35=(a34*a31);
  a36=(a27+a35);
  a37=arg[2]? arg[2][15] : 0;
  a38=arg[2]? arg[2][32] : 0;
  a23=(a23+a38);
  a23=(a23+a02);
  a23=(a23+a09);
  a09=sin(a23);
  a02=(a37*a09);
  a36=(a36+a02);
  a33=(a33*a36);
  a00=(a00-a33);
  a33=arg[2]? arg[2][16] : 0;
  a38=(a29*a33);
  a27=(a27+a35);
  a39=arg[2]? arg[2][12] : 0;
  a40=(a39*a09);
  a27=(a27+a40);
  a38=(a38*a27);
  a00=(a00-a38);
  a38=arg[2]? arg[2][18] : 0;
  a41=(a38*a18);
  a07=cos(a07);
  a42=(a03*a07);
  a24=cos(a24);
  a43=(a28*a24);
  a43=(a42+a43);
  a41=(a41*a43);
  a00=(a00+a41);
  a41=(a38*a19);
  a44=(a34*a24);
  a45=(a42+a44);
  a23=cos(a23);
  a46=(a37*a23);
  a45=(a45+a46);
  a41=(a41*a45);
  a00=(a00+a41);
  a41=(a38*a33);
  a42=(a42+a44);
  a47=(a39*a23);
  a42=(a42+a47);
  a41=(a41*a42);
  a00=(a00+a41);
  a43=(a18*a43);
  a04=casadi_sq(a04);
  a41=(a03*a04);
  a41=(a41*a06);
  a16=casadi_sq(a16);
  a48=(a28*a16);
  a48=(a48*a31);
  a48=(a41+a48);
  a43=(a43*a48);
  a00=(a00+a43);
  a32=(a18*a32);
  a03=(a03*a04);
  a03=(a03*a07);
  a43=(a28*a16);
  a43=(a43*a24);
  a43=(a03+a43);
  a32=(a32*a43);
  a00=(a00-a32);
  a45=(a19*a45);
  a32=(a34*a16);
  a32=(a32*a31);
  a49=(a41+a32);
  a50=(a37*a16);
  a50=(a50*a09);
  a49=(a49+a50);
  a45=(a45*a49);
  a00=(a00+a45);
  a36=(a19*a36);
  a34=(a34*a16);
  a34=(a34*a24);
  a45=(a03+a34);
  a37=(a37*a16);
  a37=(a37*a23);
  a45=(a45+a37);
  a36=(a36*a45);
  a00=(a00-a36);
  a42=(a33*a42);
  a41=(a41+a32);
  a32=(a39*a16);
  a32=(a32*a09);
  a41=(a41+a32);
  a42=(a42*a41);
  a00=(a00+a42);
  a27=(a33*a27);
  a03=(a03+a34);
  a39=(a39*a16);
  a39=(a39*a23);
  a03=(a03+a39);
  a27=(a27*a03);
  a00=(a00-a27);
  a27=arg[2]? arg[2][7] : 0;
  a39=(a27*a38);
  a23=arg[2]? arg[2][5] : 0;
  a39=(a39*a23);
  a39=(a39*a07);
  a00=(a00+a39);
  a39=(a27*a29);
  a39=(a39*a23);
  a39=(a39*a06);
  a00=(a00-a39);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[1]? arg[1][1] : 0;
  a00=(a00-a25);
  a25=(a29*a19);
  a02=(a35+a02);
  a25=(a25*a02);
  a00=(a00-a25);
  a25=(a29*a33);
  a35=(a35+a40);
  a25=(a25*a35);
  a00=(a00-a25);
  a25=(a38*a19);
  a46=(a44+a46);
  a25=(a25*a46);
  a00=(a00+a25);
  a25=(a38*a33);
  a44=(a44+a47);
  a25=(a25*a44);
  a00=(a00+a25);
  a46=(a19*a46);
  a46=(a46*a49);
  a00=(a00+a46);
  a02=(a19*a02);
  a02=(a02*a45);
  a00=(a00-a02);
  a44=(a33*a44);
  a44=(a44*a41);
  a00=(a00+a44);
  a35=(a33*a35);
  a35=(a35*a03);
  a00=(a00-a35);
  a35=(a28*a38);
  a35=(a35*a18);
  a35=(a35*a24);
  a00=(a00+a35);
  a35=(a28*a18);
  a35=(a35*a43);
  a35=(a35*a31);
  a00=(a00-a35);
  a35=(a28*a29);
  a35=(a35*a18);
  a35=(a35*a31);
  a00=(a00-a35);
  a28=(a28*a18);
  a28=(a28*a48);
  a28=(a28*a24);
  a00=(a00+a28);
  if (res[0]!=0) res[0][1]=a00;
  a00=(a01/a17);
  a00=(a00*a13);
  a00=(a00*a05);
  a00=(a00*a21);
  a00=(a00*a14);
  a00=(a00*a12);
  a28=(a13*a21);
  a28=(a28*a10);
  a00=(a00-a28);
  a28=(a29*a23);
  a00=(a00+a28);
  a28=(a29*a18);
  a00=(a00+a28);
  a24=(a29*a19);
  a00=(a00+a24);
  a29=(a29*a33);
  a00=(a00+a29);
  a43=(a18*a43);
  a00=(a00+a43);
  a45=(a19*a45);
  a00=(a00+a45);
  a03=(a33*a03);
  a00=(a00+a03);
  a35=(a27*a23);
  a35=(a35*a04);
  a35=(a35*a07);
  a00=(a00+a35);
  if (res[0]!=0) res[0][2]=a00;
  a00=(a38*a23);
  a35=(a13*a21);
  a35=(a35*a12);
  a17=(a01/a17);
  a17=(a17*a13);
  a17=(a17*a05);
  a17=(a17*a21);
  a17=(a17*a14);
  a17=(a17*a10);
  a35=(a35+a17);
  a00=(a00-a35);
  a35=(a38*a18);
  a00=(a00+a35);
  a17=(a38*a19);
  a00=(a00+a17);
  a38=(a38*a33);
  a00=(a00+a38);
  a18=(a18*a48);
  a00=(a00+a18);
  a19=(a19*a49);
  a00=(a00+a19);
  a33=(a33*a41);
  a00=(a00+a33);
  a27=(a27*a23);
  a27=(a27*a04);
  a27=(a27*a06);
  a00=(a00+a27);
  if (res[0]!=0) res[0][3]=a00;
  a00=(a01/a15);
  a00=(a00*a11);
  a00=(a00*a30);
  a00=(a00*a20);
  a00=(a00*a22);
  a00=(a00*a26);
  a27=(a11*a20);
  a27=(a27*a08);
  a00=(a00-a27);
  a00=(a00+a28);
  a00=(a00+a24);
  a00=(a00+a29);
  a00=(a00+a43);
  a00=(a00+a45);
  a00=(a00+a03);
  if (res[0]!=0) res[0][4]=a00;
  a00=(a11*a20);
  a00=(a00*a26);
  a01=(a01/a15);
  a01=(a01*a11);
  a01=(a01*a30);
  a01=(a01*a20);
  a01=(a01*a22);
  a01=(a01*a08);
  a00=(a00+a01);
  a35=(a35-a00);
  a35=(a35+a17);
  a35=(a35+a38);
  a35=(a35+a18);
  a35=(a35+a19);
  a35=(a35+a33);
  if (res[0]!=0) res[0][5]=a35;
  return 0;
}

CASADI_SYMBOL_EXPORT int forcing(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f1(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int forcing_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void forcing_release(int mem) {
}

CASADI_SYMBOL_EXPORT void forcing_incref(void) {
}

CASADI_SYMBOL_EXPORT void forcing_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int forcing_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int forcing_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real forcing_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* forcing_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau";
    case 2: return "p";
    case 3: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* forcing_name_out(casadi_int i) {
  switch (i) {
    case 0: return "f";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* forcing_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    case 2: return casadi_s1;
    case 3: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* forcing_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int forcing_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int forcing_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* forward_dynamics:(x[12],tau[2],p[39],v_imp[2])->(xdot[12]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real **res1=res+1, *rr, *w1=w+51, *w2=w+57, *w4=w+59, *w6=w+61;
  const casadi_real **arg1=arg+4, *ss, *wr0, *wr1, *wr3, *wr5;
  wr0 = arg[0] ? arg[0] : casadi_zeros;
  wr1 = wr0+6;
  casadi_copy(wr1, 6, res[0]);
  casadi_copy(arg[1], 2, w2);
  wr3 = arg[2] ? arg[2] : casadi_zeros;
  casadi_copy(arg[3], 2, w4);
  arg1[0]=wr0;
  arg1[1]=w2;
  arg1[2]=wr3;
  arg1[3]=w4;
  res1[0]=w1;
  if (casadi_f1(arg1, res1, iw, w, 0)) return 1;
  wr5 = wr0+0;
  arg1[0]=wr5;
  arg1[1]=wr3;
  res1[0]=w6;
  if (casadi_f0(arg1, res1, iw, w, 0)) return 1;
  rr = w1;
  ss = w6;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 1, casadi_s6, lt, d, casadi_s7, w);
  }
  if (res[0]) casadi_copy(w1, 6, res[0]+6);
  return 0;
}

CASADI_SYMBOL_EXPORT int forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f2(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int forward_dynamics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void forward_dynamics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void forward_dynamics_incref(void) {
}

CASADI_SYMBOL_EXPORT void forward_dynamics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int forward_dynamics_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int forward_dynamics_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real forward_dynamics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* forward_dynamics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau";
    case 2: return "p";
    case 3: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* forward_dynamics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "xdot";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* forward_dynamics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    case 2: return casadi_s1;
    case 3: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* forward_dynamics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 97;
  return 0;
}

CASADI_SYMBOL_EXPORT int forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 97*sizeof(casadi_real);
  return 0;
}

/* residual_jacobian:(i0[12],i1[6],i2[2],i3[39],i4[2])->(o0[6x12,52nz],o1[6x2,2nz],o2[6x39,157nz],o3[6x2,7nz]) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  casadi_real a120, a121, a122, a123, a124, a125, a126, a127, a128, a129, a130, a131;
  casadi_real a132, a133, a134, a135, a136, a137, a138, a139, a140, a141, a142, a143;
  casadi_real a144, a145, a146, a147, a148, a149, a150, a151, a152, a153, a154, a155;
  casadi_real a156, a157, a158, a159, a160, a161, a162, a163, a164, a165, a166, a167;
  casadi_real a168, a169, a170, a171, a172, a173, a174, a175, a176, a177, a178, a179;
  casadi_real a180, a181, a182, a183, a184, a185, a186, a187, a188, a189, a190, a191;
  casadi_real a192, a193, a194, a195, a196, a197, a198, a199, a200, a201, a202, a203;
  casadi_real a204, a205, a206, a207, a208, a209, a210, a211, a212, a213, a214, a215;
  casadi_real a216, a217, a218, a219, a220, a221, a222, a223, a224, a225, a226, a227;
  casadi_real a228, a229, a230, a231, a232, a233, a234, a235, a236, a237, a238, a239;
  casadi_real a240, a241, a242, a243, a244, a245, a246, a247, a248, a249, a250, a251;
  casadi_real a252, a253, a254, a255, a256, a257, a258, a259, a260, a261, a262, a263;
  casadi_real a264, a265, a266, a267, a268, a269, a270, a271, a272, a273, a274, a275;
  casadi_real a276, a277, a278, a279, a280, a281, a282, a283, a284, a285, a286, a287;
  casadi_real a288, a289, a290, a291;
  a000=arg[1]? arg[1][0] : 0;
  a001=arg[3]? arg[3][9] : 0;
  a002=arg[3]? arg[3][4] : 0;
  a003=arg[3]? arg[3][19] : 0;
  a004=arg[0]? arg[0][0] : 0;
  a005=(a003+a004);
  a006=sin(a005);
  a007=(a002*a006);
  a008=arg[3]? arg[3][11] : 0;
  a009=(a003+a004);
  a010=arg[0]? arg[0][1] : 0;
  a009=(a009+a010);
  a011=sin(a009);
  a012=(a008*a011);
  a012=(a007+a012);
  a013=(2.*a012);
  a014=cos(a005);
  a015=(a002*a014);
  a016=cos(a009);
  a017=(a008*a016);
  a017=(a015+a017);
  a018=(a013*a017);
  a019=cos(a005);
  a020=(a002*a019);
  a021=cos(a009);
  a022=(a008*a021);
  a022=(a020+a022);
  a023=(2.*a022);
  a024=sin(a005);
  a025=(a002*a024);
  a026=sin(a009);
  a027=(a008*a026);
  a027=(a025+a027);
  a028=(a023*a027);
  a018=(a018-a028);
  a018=(a001*a018);
  a028=arg[3]? arg[3][13] : 0;
  a029=arg[3]? arg[3][8] : 0;
  a030=(a029*a011);
  a031=(a007+a030);
  a032=arg[3]? arg[3][15] : 0;
  a033=arg[3]? arg[3][32] : 0;
  a003=(a003+a033);
  a003=(a003+a004);
  a003=(a003+a010);
  a010=sin(a003);
  a004=(a032*a010);
  a031=(a031+a004);
  a033=(2.*a031);
  a034=(a029*a016);
  a035=(a015+a034);
  a036=cos(a003);
  a037=(a032*a036);
  a035=(a035+a037);
  a038=(a033*a035);
  a039=(a029*a021);
  a040=(a020+a039);
  a041=cos(a003);
  a042=(a032*a041);
  a040=(a040+a042);
  a043=(2.*a040);
  a044=(a029*a026);
  a045=(a025+a044);
  a046=sin(a003);
  a047=(a032*a046);
  a045=(a045+a047);
  a048=(a043*a045);
  a038=(a038-a048);
  a038=(a028*a038);
  a018=(a018+a038);
  a038=arg[3]? arg[3][16] : 0;
  a007=(a007+a030);
  a048=arg[3]? arg[3][12] : 0;
  a049=(a048*a010);
  a007=(a007+a049);
  a050=(2.*a007);
  a015=(a015+a034);
  a051=(a048*a036);
  a015=(a015+a051);
  a052=(a050*a015);
  a020=(a020+a039);
  a053=(a048*a041);
  a020=(a020+a053);
  a054=(2.*a020);
  a025=(a025+a044);
  a055=(a048*a046);
  a025=(a025+a055);
  a056=(a054*a025);
  a052=(a052-a056);
  a052=(a038*a052);
  a018=(a018+a052);
  a018=(a000*a018);
  a052=arg[1]? arg[1][1] : 0;
  a056=(a008*a017);
  a056=(a011*a056);
  a057=(a008*a012);
  a058=(a057*a016);
  a056=(a056+a058);
  a058=(a008*a027);
  a058=(a021*a058);
  a059=(a008*a022);
  a060=(a059*a026);
  a058=(a058+a060);
  a056=(a056-a058);
  a056=(a001*a056);
  a037=(a034+a037);
  a058=(a031*a037);
  a004=(a030+a004);
  a060=(a004*a035);
  a058=(a058+a060);
  a047=(a044+a047);
  a060=(a040*a047);
  a042=(a039+a042);
  a061=(a042*a045);
  a060=(a060+a061);
  a058=(a058-a060);
  a058=(a028*a058);
  a056=(a056+a058);
  a034=(a034+a051);
  a051=(a007*a034);
  a030=(a030+a049);
  a049=(a030*a015);
  a051=(a051+a049);
  a044=(a044+a055);
  a055=(a020*a044);
  a039=(a039+a053);
  a053=(a039*a025);
  a055=(a055+a053);
  a051=(a051-a055);
  a051=(a038*a051);
  a056=(a056+a051);
  a051=(a052*a056);
  a018=(a018+a051);
  a051=arg[1]? arg[1][2] : 0;
  a055=(a001*a017);
  a053=(a028*a035);
  a049=(a055+a053);
  a058=(a038*a015);
  a049=(a049+a058);
  a060=arg[3]? arg[3][7] : 0;
  a061=arg[3]? arg[3][5] : 0;
  a062=(a060*a061);
  a063=(a062*a014);
  a049=(a049+a063);
  a063=(a051*a049);
  a018=(a018-a063);
  a063=arg[1]? arg[1][3] : 0;
  a064=(a001*a027);
  a065=(a028*a045);
  a066=(a064+a065);
  a067=(a038*a025);
  a066=(a066+a067);
  a068=(a060*a061);
  a069=(a068*a024);
  a066=(a066+a069);
  a069=(a063*a066);
  a018=(a018-a069);
  a069=arg[1]? arg[1][4] : 0;
  a055=(a055+a053);
  a055=(a055+a058);
  a058=(a069*a055);
  a018=(a018-a058);
  a058=arg[1]? arg[1][5] : 0;
  a064=(a064+a065);
  a064=(a064+a067);
  a067=(a058*a064);
  a018=(a018-a067);
  a067=(a001*a022);
  a065=arg[0]? arg[0][6] : 0;
  a053=casadi_sq(a065);
  a070=(a002*a053);
  a071=(a070*a014);
  a072=arg[0]? arg[0][7] : 0;
  a072=(a065+a072);
  a073=casadi_sq(a072);
  a074=(a008*a073);
  a075=(a074*a016);
  a075=(a071+a075);
  a076=(a067*a075);
  a077=(a070*a006);
  a078=(a074*a011);
  a078=(a077+a078);
  a079=(a001*a027);
  a079=(a078*a079);
  a076=(a076-a079);
  a079=arg[3]? arg[3][17] : 0;
  a080=(a079*a001);
  a081=(a080*a017);
  a082=(a079*a028);
  a083=(a082*a035);
  a081=(a081+a083);
  a083=(a079*a038);
  a084=(a083*a015);
  a081=(a081+a084);
  a084=arg[3]? arg[3][18] : 0;
  a085=(a084*a001);
  a027=(a085*a027);
  a081=(a081+a027);
  a027=(a084*a028);
  a086=(a027*a045);
  a081=(a081+a086);
  a086=(a084*a038);
  a087=(a086*a025);
  a081=(a081+a087);
  a076=(a076-a081);
  a081=(a002*a053);
  a087=(a081*a019);
  a088=(a008*a073);
  a089=(a088*a021);
  a089=(a087+a089);
  a017=(a001*a017);
  a017=(a089*a017);
  a090=(a001*a012);
  a091=(a081*a024);
  a092=(a088*a026);
  a092=(a091+a092);
  a093=(a090*a092);
  a017=(a017-a093);
  a076=(a076-a017);
  a017=(a028*a040);
  a093=(a029*a073);
  a094=(a093*a016);
  a095=(a071+a094);
  a096=(a032*a073);
  a097=(a096*a036);
  a095=(a095+a097);
  a097=(a017*a095);
  a098=(a093*a011);
  a099=(a077+a098);
  a100=(a096*a010);
  a099=(a099+a100);
  a045=(a028*a045);
  a045=(a099*a045);
  a097=(a097-a045);
  a076=(a076+a097);
  a097=(a029*a073);
  a045=(a097*a021);
  a100=(a087+a045);
  a101=(a032*a073);
  a102=(a101*a041);
  a100=(a100+a102);
  a035=(a028*a035);
  a035=(a100*a035);
  a102=(a028*a031);
  a103=(a097*a026);
  a104=(a091+a103);
  a105=(a101*a046);
  a104=(a104+a105);
  a105=(a102*a104);
  a035=(a035-a105);
  a076=(a076-a035);
  a035=(a038*a020);
  a071=(a071+a094);
  a094=(a048*a073);
  a105=(a094*a036);
  a071=(a071+a105);
  a105=(a035*a071);
  a077=(a077+a098);
  a098=(a094*a010);
  a077=(a077+a098);
  a025=(a038*a025);
  a025=(a077*a025);
  a105=(a105-a025);
  a076=(a076+a105);
  a087=(a087+a045);
  a045=(a048*a073);
  a105=(a045*a041);
  a087=(a087+a105);
  a015=(a038*a015);
  a015=(a087*a015);
  a105=(a038*a007);
  a091=(a091+a103);
  a103=(a045*a046);
  a091=(a091+a103);
  a103=(a105*a091);
  a015=(a015-a103);
  a076=(a076-a015);
  a015=(a060*a084);
  a103=(a015*a061);
  a025=(a103*a024);
  a076=(a076-a025);
  a025=(a060*a079);
  a098=(a025*a061);
  a106=(a098*a014);
  a076=(a076-a106);
  a018=(a018-a076);
  if (res[0]!=0) res[0][0]=a018;
  a056=(a000*a056);
  a018=(2.*a004);
  a076=(a018*a037);
  a106=(2.*a042);
  a107=(a106*a047);
  a076=(a076-a107);
  a076=(a028*a076);
  a107=(2.*a030);
  a108=(a107*a034);
  a109=(2.*a039);
  a110=(a109*a044);
  a108=(a108-a110);
  a108=(a038*a108);
  a076=(a076+a108);
  a076=(a052*a076);
  a056=(a056+a076);
  a076=(a028*a037);
  a108=(a038*a034);
  a076=(a076+a108);
  a108=(a008*a001);
  a110=(a108*a016);
  a076=(a076+a110);
  a110=(a051*a076);
  a056=(a056-a110);
  a110=(a028*a047);
  a111=(a038*a044);
  a110=(a110+a111);
  a111=(a008*a001);
  a112=(a111*a026);
  a110=(a110+a112);
  a112=(a063*a110);
  a056=(a056-a112);
  a112=(a069*a076);
  a056=(a056-a112);
  a112=(a058*a110);
  a056=(a056-a112);
  a112=(a028*a042);
  a113=(a112*a095);
  a114=(a028*a047);
  a114=(a099*a114);
  a113=(a113-a114);
  a114=(a079*a028);
  a115=(a114*a037);
  a116=(a079*a038);
  a117=(a116*a034);
  a115=(a115+a117);
  a117=(a084*a028);
  a047=(a117*a047);
  a115=(a115+a047);
  a047=(a084*a038);
  a118=(a047*a044);
  a115=(a115+a118);
  a113=(a113-a115);
  a037=(a028*a037);
  a037=(a100*a037);
  a115=(a028*a004);
  a118=(a115*a104);
  a037=(a037-a118);
  a113=(a113-a037);
  a037=(a038*a039);
  a118=(a037*a071);
  a044=(a038*a044);
  a044=(a077*a044);
  a118=(a118-a044);
  a113=(a113+a118);
  a034=(a038*a034);
  a034=(a087*a034);
  a118=(a038*a030);
  a044=(a118*a091);
  a034=(a034-a044);
  a113=(a113-a034);
  a034=(a008*a084);
  a044=(a034*a001);
  a119=(a044*a026);
  a113=(a113-a119);
  a119=(a008*a001);
  a120=(a119*a089);
  a121=(a120*a016);
  a122=(a119*a092);
  a122=(a011*a122);
  a121=(a121-a122);
  a113=(a113-a121);
  a121=(a008*a079);
  a122=(a121*a001);
  a123=(a122*a016);
  a113=(a113-a123);
  a123=(a008*a001);
  a124=(a123*a075);
  a124=(a021*a124);
  a125=(a123*a078);
  a126=(a125*a026);
  a124=(a124-a126);
  a113=(a113+a124);
  a056=(a056-a113);
  if (res[0]!=0) res[0][1]=a056;
  a092=(a001*a092);
  a104=(a028*a104);
  a056=(a092+a104);
  a091=(a038*a091);
  a056=(a056+a091);
  a113=(a060*a061);
  a124=(a113*a053);
  a024=(a124*a024);
  a056=(a056+a024);
  a049=(a000*a049);
  a024=(a052*a076);
  a049=(a049+a024);
  a056=(a056-a049);
  if (res[0]!=0) res[0][2]=a056;
  a066=(a000*a066);
  a056=(a052*a110);
  a066=(a066+a056);
  a075=(a001*a075);
  a095=(a028*a095);
  a056=(a075+a095);
  a071=(a038*a071);
  a056=(a056+a071);
  a049=(a060*a061);
  a024=(a049*a053);
  a014=(a024*a014);
  a056=(a056+a014);
  a066=(a066+a056);
  a066=(-a066);
  if (res[0]!=0) res[0][3]=a066;
  a092=(a092+a104);
  a092=(a092+a091);
  a055=(a000*a055);
  a076=(a052*a076);
  a055=(a055+a076);
  a092=(a092-a055);
  if (res[0]!=0) res[0][4]=a092;
  a064=(a000*a064);
  a110=(a052*a110);
  a064=(a064+a110);
  a075=(a075+a095);
  a075=(a075+a071);
  a064=(a064+a075);
  a064=(-a064);
  if (res[0]!=0) res[0][5]=a064;
  a064=(a008*a016);
  a013=(a013*a064);
  a075=(a008*a026);
  a023=(a023*a075);
  a013=(a013-a023);
  a013=(a001*a013);
  a023=(a029*a016);
  a071=(a032*a036);
  a095=(a023+a071);
  a033=(a033*a095);
  a110=(a029*a026);
  a092=(a032*a046);
  a055=(a110+a092);
  a043=(a043*a055);
  a033=(a033-a043);
  a033=(a028*a033);
  a013=(a013+a033);
  a033=(a048*a036);
  a043=(a023+a033);
  a050=(a050*a043);
  a076=(a048*a046);
  a091=(a110+a076);
  a054=(a054*a091);
  a050=(a050-a054);
  a050=(a038*a050);
  a013=(a013+a050);
  a013=(a000*a013);
  a050=(a008*a064);
  a050=(a011*a050);
  a054=(a057*a016);
  a050=(a050+a054);
  a054=(a008*a075);
  a054=(a021*a054);
  a104=(a059*a026);
  a054=(a054+a104);
  a050=(a050-a054);
  a050=(a001*a050);
  a071=(a023+a071);
  a054=(a031*a071);
  a104=(a004*a095);
  a054=(a054+a104);
  a092=(a110+a092);
  a104=(a040*a092);
  a066=(a042*a055);
  a104=(a104+a066);
  a054=(a054-a104);
  a054=(a028*a054);
  a050=(a050+a054);
  a023=(a023+a033);
  a033=(a007*a023);
  a054=(a030*a043);
  a033=(a033+a054);
  a110=(a110+a076);
  a076=(a020*a110);
  a054=(a039*a091);
  a076=(a076+a054);
  a033=(a033-a076);
  a033=(a038*a033);
  a050=(a050+a033);
  a033=(a052*a050);
  a013=(a013+a033);
  a033=(a001*a064);
  a076=(a028*a095);
  a054=(a033+a076);
  a104=(a038*a043);
  a054=(a054+a104);
  a066=(a051*a054);
  a013=(a013-a066);
  a066=(a001*a075);
  a056=(a028*a055);
  a014=(a066+a056);
  a126=(a038*a091);
  a014=(a014+a126);
  a127=(a063*a014);
  a013=(a013-a127);
  a033=(a033+a076);
  a033=(a033+a104);
  a104=(a069*a033);
  a013=(a013-a104);
  a066=(a066+a056);
  a066=(a066+a126);
  a126=(a058*a066);
  a013=(a013-a126);
  a126=(a074*a016);
  a056=(a067*a126);
  a104=(a001*a075);
  a104=(a078*a104);
  a056=(a056-a104);
  a104=(a080*a064);
  a076=(a082*a095);
  a104=(a104+a076);
  a076=(a083*a043);
  a104=(a104+a076);
  a075=(a085*a075);
  a104=(a104+a075);
  a075=(a027*a055);
  a104=(a104+a075);
  a075=(a086*a091);
  a104=(a104+a075);
  a056=(a056-a104);
  a064=(a001*a064);
  a064=(a089*a064);
  a104=(a088*a026);
  a075=(a090*a104);
  a064=(a064-a075);
  a056=(a056-a064);
  a064=(a093*a016);
  a075=(a096*a036);
  a075=(a064+a075);
  a076=(a017*a075);
  a055=(a028*a055);
  a055=(a099*a055);
  a076=(a076-a055);
  a056=(a056+a076);
  a095=(a028*a095);
  a095=(a100*a095);
  a076=(a097*a026);
  a055=(a101*a046);
  a055=(a076+a055);
  a127=(a102*a055);
  a095=(a095-a127);
  a056=(a056-a095);
  a036=(a094*a036);
  a064=(a064+a036);
  a036=(a035*a064);
  a091=(a038*a091);
  a091=(a077*a091);
  a036=(a036-a091);
  a056=(a056+a036);
  a043=(a038*a043);
  a043=(a087*a043);
  a046=(a045*a046);
  a076=(a076+a046);
  a046=(a105*a076);
  a043=(a043-a046);
  a056=(a056-a043);
  a013=(a013-a056);
  if (res[0]!=0) res[0][6]=a013;
  a050=(a000*a050);
  a018=(a018*a071);
  a106=(a106*a092);
  a018=(a018-a106);
  a018=(a028*a018);
  a107=(a107*a023);
  a109=(a109*a110);
  a107=(a107-a109);
  a107=(a038*a107);
  a018=(a018+a107);
  a018=(a052*a018);
  a050=(a050+a018);
  a018=(a028*a071);
  a107=(a038*a023);
  a018=(a018+a107);
  a107=(a108*a016);
  a018=(a018+a107);
  a107=(a051*a018);
  a050=(a050-a107);
  a107=(a028*a092);
  a109=(a038*a110);
  a107=(a107+a109);
  a109=(a111*a026);
  a107=(a107+a109);
  a109=(a063*a107);
  a050=(a050-a109);
  a109=(a069*a018);
  a050=(a050-a109);
  a109=(a058*a107);
  a050=(a050-a109);
  a109=(a112*a075);
  a106=(a028*a092);
  a106=(a099*a106);
  a109=(a109-a106);
  a106=(a114*a071);
  a013=(a116*a023);
  a106=(a106+a013);
  a092=(a117*a092);
  a106=(a106+a092);
  a092=(a047*a110);
  a106=(a106+a092);
  a109=(a109-a106);
  a071=(a028*a071);
  a071=(a100*a071);
  a106=(a115*a055);
  a071=(a071-a106);
  a109=(a109-a071);
  a071=(a037*a064);
  a110=(a038*a110);
  a110=(a077*a110);
  a071=(a071-a110);
  a109=(a109+a071);
  a023=(a038*a023);
  a023=(a087*a023);
  a071=(a118*a076);
  a023=(a023-a071);
  a109=(a109-a023);
  a023=(a044*a026);
  a109=(a109-a023);
  a023=(a120*a016);
  a071=(a119*a104);
  a071=(a011*a071);
  a023=(a023-a071);
  a109=(a109-a023);
  a016=(a122*a016);
  a109=(a109-a016);
  a016=(a123*a126);
  a016=(a021*a016);
  a026=(a125*a026);
  a016=(a016-a026);
  a109=(a109+a016);
  a050=(a050-a109);
  if (res[0]!=0) res[0][7]=a050;
  a104=(a001*a104);
  a055=(a028*a055);
  a050=(a104+a055);
  a076=(a038*a076);
  a050=(a050+a076);
  a054=(a000*a054);
  a109=(a052*a018);
  a054=(a054+a109);
  a050=(a050-a054);
  if (res[0]!=0) res[0][8]=a050;
  a014=(a000*a014);
  a050=(a052*a107);
  a014=(a014+a050);
  a126=(a001*a126);
  a075=(a028*a075);
  a050=(a126+a075);
  a064=(a038*a064);
  a050=(a050+a064);
  a014=(a014+a050);
  a014=(-a014);
  if (res[0]!=0) res[0][9]=a014;
  a104=(a104+a055);
  a104=(a104+a076);
  a033=(a000*a033);
  a018=(a052*a018);
  a033=(a033+a018);
  a104=(a104-a033);
  if (res[0]!=0) res[0][10]=a104;
  a066=(a000*a066);
  a107=(a052*a107);
  a066=(a066+a107);
  a126=(a126+a075);
  a126=(a126+a064);
  a066=(a066+a126);
  a066=(-a066);
  if (res[0]!=0) res[0][11]=a066;
  a066=arg[3]? arg[3][21] : 0;
  a126=1.;
  a064=0.;
  a075=(a066*a065);
  a107=-9.9999999999999995e-07;
  a104=(a107*a066);
  a033=9.9999999999999995e-07;
  a018=arg[3]? arg[3][20] : 0;
  a076=(a033*a018);
  a104=(a104+a076);
  a076=casadi_sq(a104);
  a055=arg[0]? arg[0][2] : 0;
  a014=casadi_sq(a055);
  a050=arg[0]? arg[0][3] : 0;
  a054=casadi_sq(a050);
  a014=(a014+a054);
  a054=casadi_fmax(a076,a014);
  a109=-5.0000000000000000e-01;
  a016=pow(a054,a109);
  a026=(a016*a055);
  a023=arg[0]? arg[0][9] : 0;
  a071=(a026*a023);
  a075=(a075+a071);
  a071=(a016*a050);
  a110=arg[0]? arg[0][8] : 0;
  a106=(a071*a110);
  a075=(a075-a106);
  a106=casadi_fabs(a075);
  a092=arg[3]? arg[3][37] : 0;
  a013=(a106-a092);
  a056=arg[3]? arg[3][38] : 0;
  a056=(a056-a092);
  a013=(a013/a056);
  a043=casadi_fmax(a064,a013);
  a046=casadi_fmin(a126,a043);
  a036=1.3333333333333333e+00;
  a091=(a018*a066);
  a095=(a018-a066);
  a091=(a091/a095);
  a127=sqrt(a091);
  a128=(a036*a127);
  a129=arg[3]? arg[3][23] : 0;
  a130=casadi_sq(a129);
  a130=(a126-a130);
  a131=arg[3]? arg[3][22] : 0;
  a130=(a130/a131);
  a132=arg[3]? arg[3][25] : 0;
  a133=casadi_sq(a132);
  a133=(a126-a133);
  a134=arg[3]? arg[3][24] : 0;
  a133=(a133/a134);
  a135=(a130+a133);
  a128=(a128/a135);
  a136=sqrt(a054);
  a137=(a066+a136);
  a137=(a137-a018);
  a138=casadi_fmax(a064,a137);
  a139=arg[3]? arg[3][33] : 0;
  a140=pow(a138,a139);
  a141=(a128*a140);
  a142=7.5000000000000000e-01;
  a143=-7.5000000000000000e-01;
  a144=arg[3]? arg[3][34] : 0;
  a145=casadi_sq(a144);
  a145=(a143*a145);
  a142=(a142+a145);
  a145=arg[4]? arg[4][0] : 0;
  a146=arg[3]? arg[3][35] : 0;
  a147=casadi_fmax(a145,a146);
  a148=(a142/a147);
  a149=(a016*a055);
  a150=(a149*a110);
  a151=(a016*a050);
  a152=(a151*a023);
  a150=(a150+a152);
  a152=(a148*a150);
  a152=(a126+a152);
  a153=(a141*a152);
  a154=casadi_fmax(a064,a153);
  a155=arg[3]? arg[3][36] : 0;
  a156=casadi_fmax(a092,a106);
  a157=(a155/a156);
  a158=-1.5000000000000000e+00;
  a159=pow(a054,a158);
  a159=(a109*a159);
  a160=(a076<=a014);
  a161=(a014<=a076);
  a161=(a161+a160);
  a160=(a160/a161);
  a161=(2.*a055);
  a161=(a160*a161);
  a162=(a159*a161);
  a163=(a055*a162);
  a163=(a163+a016);
  a163=(a023*a163);
  a164=(a050*a162);
  a164=(a110*a164);
  a163=(a163-a164);
  a164=(a157*a163);
  a165=(a157/a156);
  a166=(a092<=a106);
  a167=(a106<=a092);
  a167=(a167+a166);
  a166=(a166/a167);
  a167=casadi_sign(a075);
  a168=(a167*a163);
  a169=(a166*a168);
  a170=(a165*a169);
  a170=(a075*a170);
  a164=(a164-a170);
  a164=(a154*a164);
  a170=(a157*a075);
  a171=(a064<=a153);
  a172=(a153<=a064);
  a172=(a172+a171);
  a171=(a171/a172);
  a172=(a139-a126);
  a172=pow(a138,a172);
  a172=(a139*a172);
  a173=(a064<=a137);
  a174=(a137<=a064);
  a174=(a174+a173);
  a173=(a173/a174);
  a174=(2.*a136);
  a161=(a161/a174);
  a161=(a173*a161);
  a161=(a172*a161);
  a161=(a128*a161);
  a161=(a152*a161);
  a175=(a055*a162);
  a175=(a175+a016);
  a175=(a110*a175);
  a176=(a050*a162);
  a176=(a023*a176);
  a175=(a175+a176);
  a175=(a148*a175);
  a175=(a141*a175);
  a161=(a161+a175);
  a161=(a171*a161);
  a175=(a170*a161);
  a164=(a164+a175);
  a164=(a046*a164);
  a175=(a170*a154);
  a176=(a043<=a126);
  a177=(a126<=a043);
  a177=(a177+a176);
  a176=(a176/a177);
  a177=(a064<=a013);
  a178=(a013<=a064);
  a178=(a178+a177);
  a177=(a177/a178);
  a168=(a168/a056);
  a168=(a177*a168);
  a168=(a176*a168);
  a178=(a175*a168);
  a164=(a164+a178);
  a164=(a066*a164);
  if (res[0]!=0) res[0][12]=a164;
  a164=(a155/a156);
  a178=(a164*a162);
  a179=(a164/a156);
  a180=(a179*a169);
  a180=(a016*a180);
  a178=(a178-a180);
  a178=(a075*a178);
  a180=(a164*a016);
  a181=(a180*a163);
  a178=(a178+a181);
  a178=(a154*a178);
  a181=(a180*a075);
  a182=(a181*a161);
  a178=(a178+a182);
  a178=(a046*a178);
  a182=(a181*a154);
  a183=(a182*a168);
  a178=(a178+a183);
  a178=(a050*a178);
  a183=(a154*a162);
  a184=(a016*a161);
  a183=(a183+a184);
  a183=(a055*a183);
  a184=(a016*a154);
  a183=(a183+a184);
  a178=(a178-a183);
  a178=(-a178);
  if (res[0]!=0) res[0][13]=a178;
  a178=(a154*a162);
  a183=(a016*a161);
  a178=(a178+a183);
  a178=(a050*a178);
  a183=(a155/a156);
  a162=(a183*a162);
  a184=(a183/a156);
  a169=(a184*a169);
  a169=(a016*a169);
  a162=(a162-a169);
  a162=(a075*a162);
  a169=(a183*a016);
  a163=(a169*a163);
  a162=(a162+a163);
  a162=(a154*a162);
  a163=(a169*a075);
  a161=(a163*a161);
  a162=(a162+a161);
  a162=(a046*a162);
  a161=(a163*a154);
  a168=(a161*a168);
  a162=(a162+a168);
  a162=(a055*a162);
  a168=(a161*a046);
  a162=(a162+a168);
  a178=(a178+a162);
  if (res[0]!=0) res[0][14]=a178;
  a178=(2.*a050);
  a160=(a160*a178);
  a159=(a159*a160);
  a178=(a055*a159);
  a178=(a023*a178);
  a162=(a050*a159);
  a162=(a162+a016);
  a162=(a110*a162);
  a178=(a178-a162);
  a162=(a157*a178);
  a168=(a167*a178);
  a185=(a166*a168);
  a186=(a165*a185);
  a186=(a075*a186);
  a162=(a162-a186);
  a162=(a154*a162);
  a160=(a160/a174);
  a173=(a173*a160);
  a172=(a172*a173);
  a172=(a128*a172);
  a172=(a152*a172);
  a173=(a055*a159);
  a173=(a110*a173);
  a160=(a050*a159);
  a160=(a160+a016);
  a160=(a023*a160);
  a173=(a173+a160);
  a173=(a148*a173);
  a173=(a141*a173);
  a172=(a172+a173);
  a172=(a171*a172);
  a173=(a170*a172);
  a162=(a162+a173);
  a162=(a046*a162);
  a168=(a168/a056);
  a168=(a177*a168);
  a168=(a176*a168);
  a173=(a175*a168);
  a162=(a162+a173);
  a162=(a066*a162);
  if (res[0]!=0) res[0][15]=a162;
  a162=(a164*a159);
  a173=(a179*a185);
  a173=(a016*a173);
  a162=(a162-a173);
  a162=(a075*a162);
  a173=(a180*a178);
  a162=(a162+a173);
  a162=(a154*a162);
  a173=(a181*a172);
  a162=(a162+a173);
  a162=(a046*a162);
  a173=(a182*a168);
  a162=(a162+a173);
  a162=(a050*a162);
  a173=(a182*a046);
  a162=(a162+a173);
  a173=(a154*a159);
  a160=(a016*a172);
  a173=(a173+a160);
  a173=(a055*a173);
  a162=(a162-a173);
  a162=(-a162);
  if (res[0]!=0) res[0][16]=a162;
  a162=(a154*a159);
  a173=(a016*a172);
  a162=(a162+a173);
  a162=(a050*a162);
  a173=(a016*a154);
  a162=(a162+a173);
  a159=(a183*a159);
  a185=(a184*a185);
  a185=(a016*a185);
  a159=(a159-a185);
  a159=(a075*a159);
  a178=(a169*a178);
  a159=(a159+a178);
  a159=(a154*a159);
  a172=(a163*a172);
  a159=(a159+a172);
  a159=(a046*a159);
  a168=(a161*a168);
  a159=(a159+a168);
  a159=(a055*a159);
  a162=(a162+a159);
  if (res[0]!=0) res[0][17]=a162;
  a162=arg[3]? arg[3][26] : 0;
  a159=(a162*a065);
  a168=arg[3]? arg[3][27] : 0;
  a172=(a168*a072);
  a159=(a159-a172);
  a172=(a107*a168);
  a178=(a033*a162);
  a172=(a172+a178);
  a178=casadi_sq(a172);
  a185=arg[0]? arg[0][4] : 0;
  a173=casadi_sq(a185);
  a160=arg[0]? arg[0][5] : 0;
  a174=casadi_sq(a160);
  a173=(a173+a174);
  a174=casadi_fmax(a178,a173);
  a186=pow(a174,a109);
  a187=(a186*a160);
  a188=arg[0]? arg[0][10] : 0;
  a189=(a187*a188);
  a159=(a159+a189);
  a189=(a186*a185);
  a190=arg[0]? arg[0][11] : 0;
  a191=(a189*a190);
  a159=(a159-a191);
  a191=casadi_fabs(a159);
  a192=(a191-a092);
  a192=(a192/a056);
  a193=casadi_fmax(a064,a192);
  a194=casadi_fmin(a126,a193);
  a195=(a162*a168);
  a196=(a162-a168);
  a195=(a195/a196);
  a197=sqrt(a195);
  a198=(a036*a197);
  a199=arg[3]? arg[3][29] : 0;
  a200=casadi_sq(a199);
  a200=(a126-a200);
  a201=arg[3]? arg[3][28] : 0;
  a200=(a200/a201);
  a202=arg[3]? arg[3][31] : 0;
  a203=casadi_sq(a202);
  a203=(a126-a203);
  a204=arg[3]? arg[3][30] : 0;
  a203=(a203/a204);
  a205=(a200+a203);
  a198=(a198/a205);
  a206=sqrt(a174);
  a207=(a168+a206);
  a207=(a207-a162);
  a208=casadi_fmax(a064,a207);
  a209=pow(a208,a139);
  a210=(a198*a209);
  a211=arg[4]? arg[4][1] : 0;
  a212=casadi_fmax(a211,a146);
  a142=(a142/a212);
  a213=(a186*a185);
  a214=(a213*a188);
  a215=(a186*a160);
  a216=(a215*a190);
  a214=(a214+a216);
  a216=(a142*a214);
  a216=(a126+a216);
  a217=(a210*a216);
  a218=casadi_fmax(a064,a217);
  a219=casadi_fmax(a092,a191);
  a220=(a155/a219);
  a221=pow(a174,a158);
  a221=(a109*a221);
  a222=(a178<=a173);
  a223=(a173<=a178);
  a223=(a223+a222);
  a222=(a222/a223);
  a223=(2.*a185);
  a223=(a222*a223);
  a224=(a221*a223);
  a225=(a185*a224);
  a225=(a225+a186);
  a225=(a190*a225);
  a226=(a160*a224);
  a226=(a188*a226);
  a225=(a225-a226);
  a226=(a220*a225);
  a227=(a168*a072);
  a228=(a162*a065);
  a227=(a227-a228);
  a228=(a186*a185);
  a229=(a228*a190);
  a227=(a227+a229);
  a229=(a186*a160);
  a230=(a229*a188);
  a227=(a227-a230);
  a230=(a220/a219);
  a231=(a092<=a191);
  a232=(a191<=a092);
  a232=(a232+a231);
  a231=(a231/a232);
  a232=casadi_sign(a159);
  a233=(a160*a224);
  a233=(a188*a233);
  a234=(a185*a224);
  a234=(a234+a186);
  a234=(a190*a234);
  a233=(a233-a234);
  a233=(a232*a233);
  a234=(a231*a233);
  a235=(a230*a234);
  a235=(a227*a235);
  a226=(a226-a235);
  a226=(a218*a226);
  a235=(a220*a227);
  a236=(a064<=a217);
  a237=(a217<=a064);
  a237=(a237+a236);
  a236=(a236/a237);
  a237=(a139-a126);
  a237=pow(a208,a237);
  a237=(a139*a237);
  a238=(a064<=a207);
  a239=(a207<=a064);
  a239=(a239+a238);
  a238=(a238/a239);
  a239=(2.*a206);
  a223=(a223/a239);
  a223=(a238*a223);
  a223=(a237*a223);
  a223=(a198*a223);
  a223=(a216*a223);
  a240=(a185*a224);
  a240=(a240+a186);
  a240=(a188*a240);
  a241=(a160*a224);
  a241=(a190*a241);
  a240=(a240+a241);
  a240=(a142*a240);
  a240=(a210*a240);
  a223=(a223+a240);
  a223=(a236*a223);
  a240=(a235*a223);
  a226=(a226+a240);
  a226=(a194*a226);
  a240=(a235*a218);
  a241=(a193<=a126);
  a242=(a126<=a193);
  a242=(a242+a241);
  a241=(a241/a242);
  a242=(a064<=a192);
  a243=(a192<=a064);
  a243=(a243+a242);
  a242=(a242/a243);
  a233=(a233/a056);
  a233=(a242*a233);
  a233=(a241*a233);
  a243=(a240*a233);
  a226=(a226+a243);
  a243=(a162*a226);
  a226=(a168*a226);
  a243=(a243-a226);
  a243=(-a243);
  if (res[0]!=0) res[0][18]=a243;
  if (res[0]!=0) res[0][19]=a226;
  a226=(a155/a219);
  a243=(a226*a224);
  a244=(a226/a219);
  a245=(a244*a234);
  a245=(a186*a245);
  a243=(a243-a245);
  a243=(a227*a243);
  a245=(a226*a186);
  a246=(a245*a225);
  a243=(a243+a246);
  a243=(a218*a243);
  a246=(a245*a227);
  a247=(a246*a223);
  a243=(a243+a247);
  a243=(a194*a243);
  a247=(a246*a218);
  a248=(a247*a233);
  a243=(a243+a248);
  a243=(a160*a243);
  a248=(a218*a224);
  a249=(a186*a223);
  a248=(a248+a249);
  a248=(a185*a248);
  a249=(a186*a218);
  a248=(a248+a249);
  a243=(a243-a248);
  a243=(-a243);
  if (res[0]!=0) res[0][20]=a243;
  a243=(a218*a224);
  a248=(a186*a223);
  a243=(a243+a248);
  a243=(a160*a243);
  a155=(a155/a219);
  a224=(a155*a224);
  a248=(a155/a219);
  a234=(a248*a234);
  a234=(a186*a234);
  a224=(a224-a234);
  a224=(a227*a224);
  a234=(a155*a186);
  a225=(a234*a225);
  a224=(a224+a225);
  a224=(a218*a224);
  a225=(a234*a227);
  a223=(a225*a223);
  a224=(a224+a223);
  a224=(a194*a224);
  a223=(a225*a218);
  a233=(a223*a233);
  a224=(a224+a233);
  a224=(a185*a224);
  a233=(a223*a194);
  a224=(a224+a233);
  a243=(a243+a224);
  if (res[0]!=0) res[0][21]=a243;
  a243=(2.*a160);
  a222=(a222*a243);
  a221=(a221*a222);
  a243=(a185*a221);
  a243=(a190*a243);
  a224=(a160*a221);
  a224=(a224+a186);
  a224=(a188*a224);
  a243=(a243-a224);
  a224=(a220*a243);
  a233=(a160*a221);
  a233=(a233+a186);
  a233=(a188*a233);
  a249=(a185*a221);
  a249=(a190*a249);
  a233=(a233-a249);
  a233=(a232*a233);
  a249=(a231*a233);
  a250=(a230*a249);
  a250=(a227*a250);
  a224=(a224-a250);
  a224=(a218*a224);
  a222=(a222/a239);
  a238=(a238*a222);
  a237=(a237*a238);
  a237=(a198*a237);
  a237=(a216*a237);
  a238=(a185*a221);
  a238=(a188*a238);
  a222=(a160*a221);
  a222=(a222+a186);
  a222=(a190*a222);
  a238=(a238+a222);
  a238=(a142*a238);
  a238=(a210*a238);
  a237=(a237+a238);
  a237=(a236*a237);
  a238=(a235*a237);
  a224=(a224+a238);
  a224=(a194*a224);
  a233=(a233/a056);
  a233=(a242*a233);
  a233=(a241*a233);
  a238=(a240*a233);
  a224=(a224+a238);
  a238=(a162*a224);
  a224=(a168*a224);
  a238=(a238-a224);
  a238=(-a238);
  if (res[0]!=0) res[0][22]=a238;
  if (res[0]!=0) res[0][23]=a224;
  a224=(a226*a221);
  a238=(a244*a249);
  a238=(a186*a238);
  a224=(a224-a238);
  a224=(a227*a224);
  a238=(a245*a243);
  a224=(a224+a238);
  a224=(a218*a224);
  a238=(a246*a237);
  a224=(a224+a238);
  a224=(a194*a224);
  a238=(a247*a233);
  a224=(a224+a238);
  a224=(a160*a224);
  a238=(a247*a194);
  a224=(a224+a238);
  a238=(a218*a221);
  a222=(a186*a237);
  a238=(a238+a222);
  a238=(a185*a238);
  a224=(a224-a238);
  a224=(-a224);
  if (res[0]!=0) res[0][24]=a224;
  a224=(a218*a221);
  a238=(a186*a237);
  a224=(a224+a238);
  a224=(a160*a224);
  a238=(a186*a218);
  a224=(a224+a238);
  a221=(a155*a221);
  a249=(a248*a249);
  a249=(a186*a249);
  a221=(a221-a249);
  a221=(a227*a221);
  a243=(a234*a243);
  a221=(a221+a243);
  a221=(a218*a221);
  a237=(a225*a237);
  a221=(a221+a237);
  a221=(a194*a221);
  a233=(a223*a233);
  a221=(a221+a233);
  a221=(a185*a221);
  a224=(a224+a221);
  if (res[0]!=0) res[0][25]=a224;
  a224=(a168-a162);
  a221=(a220*a224);
  a233=(a162-a168);
  a233=(a232*a233);
  a237=(a231*a233);
  a243=(a230*a237);
  a243=(a227*a243);
  a221=(a221-a243);
  a221=(a218*a221);
  a221=(a194*a221);
  a233=(a233/a056);
  a233=(a242*a233);
  a233=(a241*a233);
  a243=(a240*a233);
  a221=(a221+a243);
  a243=(a162*a221);
  a249=(a157*a066);
  a238=(a167*a066);
  a222=(a166*a238);
  a239=(a165*a222);
  a239=(a075*a239);
  a249=(a249-a239);
  a249=(a154*a249);
  a249=(a046*a249);
  a238=(a238/a056);
  a238=(a177*a238);
  a238=(a176*a238);
  a239=(a175*a238);
  a249=(a249+a239);
  a249=(a066*a249);
  a221=(a168*a221);
  a249=(a249+a221);
  a243=(a243-a249);
  a249=(2.*a065);
  a239=(a002*a249);
  a239=(a006*a239);
  a250=(2.*a072);
  a251=(a008*a250);
  a251=(a011*a251);
  a251=(a239+a251);
  a252=(a067*a251);
  a243=(a243+a252);
  a252=(a002*a249);
  a252=(a019*a252);
  a253=(a008*a250);
  a253=(a021*a253);
  a253=(a252+a253);
  a254=(a090*a253);
  a243=(a243-a254);
  a254=(a029*a250);
  a254=(a011*a254);
  a255=(a239+a254);
  a256=(a032*a250);
  a256=(a010*a256);
  a255=(a255+a256);
  a256=(a017*a255);
  a243=(a243+a256);
  a256=(a029*a250);
  a256=(a021*a256);
  a257=(a252+a256);
  a258=(a032*a250);
  a258=(a041*a258);
  a257=(a257+a258);
  a258=(a102*a257);
  a243=(a243-a258);
  a239=(a239+a254);
  a254=(a048*a250);
  a254=(a010*a254);
  a239=(a239+a254);
  a254=(a035*a239);
  a243=(a243+a254);
  a252=(a252+a256);
  a256=(a048*a250);
  a256=(a041*a256);
  a252=(a252+a256);
  a256=(a105*a252);
  a243=(a243-a256);
  a243=(-a243);
  if (res[0]!=0) res[0][26]=a243;
  a243=(a112*a255);
  a243=(a243-a221);
  a221=(a115*a257);
  a243=(a243-a221);
  a221=(a037*a239);
  a243=(a243+a221);
  a221=(a118*a252);
  a243=(a243-a221);
  a221=(a119*a253);
  a221=(a011*a221);
  a243=(a243-a221);
  a221=(a123*a251);
  a221=(a021*a221);
  a243=(a243+a221);
  a243=(-a243);
  if (res[0]!=0) res[0][27]=a243;
  a243=(a180*a066);
  a221=(a179*a222);
  a221=(a016*a221);
  a221=(a075*a221);
  a243=(a243-a221);
  a243=(a154*a243);
  a243=(a046*a243);
  a221=(a182*a238);
  a243=(a243+a221);
  a243=(a050*a243);
  a253=(a001*a253);
  a243=(a243+a253);
  a257=(a028*a257);
  a243=(a243+a257);
  a252=(a038*a252);
  a243=(a243+a252);
  a113=(a113*a249);
  a113=(a019*a113);
  a243=(a243+a113);
  a243=(-a243);
  if (res[0]!=0) res[0][28]=a243;
  a251=(a001*a251);
  a243=(a169*a066);
  a222=(a184*a222);
  a222=(a016*a222);
  a222=(a075*a222);
  a243=(a243-a222);
  a243=(a154*a243);
  a243=(a046*a243);
  a238=(a161*a238);
  a243=(a243+a238);
  a243=(a055*a243);
  a243=(a251-a243);
  a255=(a028*a255);
  a243=(a243+a255);
  a239=(a038*a239);
  a243=(a243+a239);
  a049=(a049*a249);
  a049=(a006*a049);
  a243=(a243+a049);
  a243=(-a243);
  if (res[0]!=0) res[0][29]=a243;
  a243=(a245*a224);
  a049=(a244*a237);
  a049=(a186*a049);
  a049=(a227*a049);
  a243=(a243-a049);
  a243=(a218*a243);
  a243=(a194*a243);
  a049=(a247*a233);
  a243=(a243+a049);
  a243=(a160*a243);
  a243=(a243+a253);
  a243=(a243+a257);
  a243=(a243+a252);
  a243=(-a243);
  if (res[0]!=0) res[0][30]=a243;
  a224=(a234*a224);
  a237=(a248*a237);
  a237=(a186*a237);
  a237=(a227*a237);
  a224=(a224-a237);
  a224=(a218*a224);
  a224=(a194*a224);
  a233=(a223*a233);
  a224=(a224+a233);
  a224=(a185*a224);
  a251=(a251-a224);
  a251=(a251+a255);
  a251=(a251+a239);
  a251=(-a251);
  if (res[0]!=0) res[0][31]=a251;
  a251=(a232*a168);
  a239=(a231*a251);
  a255=(a230*a239);
  a255=(a227*a255);
  a224=(a220*a168);
  a255=(a255+a224);
  a255=(a218*a255);
  a255=(a194*a255);
  a251=(a251/a056);
  a251=(a242*a251);
  a251=(a241*a251);
  a224=(a240*a251);
  a255=(a255-a224);
  a224=(a162*a255);
  a255=(a168*a255);
  a224=(a224-a255);
  a233=(a008*a250);
  a233=(a011*a233);
  a237=(a067*a233);
  a224=(a224+a237);
  a237=(a008*a250);
  a237=(a021*a237);
  a243=(a090*a237);
  a224=(a224-a243);
  a243=(a029*a250);
  a243=(a011*a243);
  a252=(a032*a250);
  a252=(a010*a252);
  a252=(a243+a252);
  a257=(a017*a252);
  a224=(a224+a257);
  a257=(a029*a250);
  a257=(a021*a257);
  a253=(a032*a250);
  a253=(a041*a253);
  a253=(a257+a253);
  a049=(a102*a253);
  a224=(a224-a049);
  a049=(a048*a250);
  a049=(a010*a049);
  a243=(a243+a049);
  a049=(a035*a243);
  a224=(a224+a049);
  a250=(a048*a250);
  a250=(a041*a250);
  a257=(a257+a250);
  a250=(a105*a257);
  a224=(a224-a250);
  a224=(-a224);
  if (res[0]!=0) res[0][32]=a224;
  a224=(a112*a252);
  a224=(a224-a255);
  a255=(a115*a253);
  a224=(a224-a255);
  a255=(a037*a243);
  a224=(a224+a255);
  a255=(a118*a257);
  a224=(a224-a255);
  a255=(a119*a237);
  a255=(a011*a255);
  a224=(a224-a255);
  a255=(a123*a233);
  a255=(a021*a255);
  a224=(a224+a255);
  a224=(-a224);
  if (res[0]!=0) res[0][33]=a224;
  a237=(a001*a237);
  a253=(a028*a253);
  a224=(a237+a253);
  a257=(a038*a257);
  a224=(a224+a257);
  a224=(-a224);
  if (res[0]!=0) res[0][34]=a224;
  a233=(a001*a233);
  a252=(a028*a252);
  a224=(a233+a252);
  a243=(a038*a243);
  a224=(a224+a243);
  a224=(-a224);
  if (res[0]!=0) res[0][35]=a224;
  a224=(a244*a239);
  a224=(a186*a224);
  a224=(a227*a224);
  a255=(a245*a168);
  a224=(a224+a255);
  a224=(a218*a224);
  a224=(a194*a224);
  a255=(a247*a251);
  a224=(a224-a255);
  a224=(a160*a224);
  a224=(a224+a237);
  a224=(a224+a253);
  a224=(a224+a257);
  a224=(-a224);
  if (res[0]!=0) res[0][36]=a224;
  a239=(a248*a239);
  a239=(a186*a239);
  a239=(a227*a239);
  a224=(a234*a168);
  a239=(a239+a224);
  a239=(a218*a239);
  a239=(a194*a239);
  a251=(a223*a251);
  a239=(a239-a251);
  a239=(a185*a239);
  a233=(a233-a239);
  a233=(a233+a252);
  a233=(a233+a243);
  a233=(-a233);
  if (res[0]!=0) res[0][37]=a233;
  a233=(a167*a071);
  a243=(a166*a233);
  a252=(a165*a243);
  a252=(a075*a252);
  a239=(a157*a071);
  a252=(a252-a239);
  a252=(a154*a252);
  a149=(a148*a149);
  a149=(a141*a149);
  a149=(a171*a149);
  a239=(a170*a149);
  a252=(a252+a239);
  a252=(a046*a252);
  a233=(a233/a056);
  a233=(a177*a233);
  a233=(a176*a233);
  a239=(a175*a233);
  a252=(a252-a239);
  a252=(a066*a252);
  if (res[0]!=0) res[0][38]=a252;
  a252=(a179*a243);
  a252=(a016*a252);
  a252=(a075*a252);
  a239=(a180*a071);
  a252=(a252-a239);
  a252=(a154*a252);
  a239=(a181*a149);
  a252=(a252+a239);
  a252=(a046*a252);
  a239=(a182*a233);
  a252=(a252-a239);
  a252=(a050*a252);
  a239=(a016*a149);
  a239=(a055*a239);
  a252=(a252-a239);
  a252=(-a252);
  if (res[0]!=0) res[0][39]=a252;
  a252=(a016*a149);
  a252=(a050*a252);
  a243=(a184*a243);
  a243=(a016*a243);
  a243=(a075*a243);
  a071=(a169*a071);
  a243=(a243-a071);
  a243=(a154*a243);
  a149=(a163*a149);
  a243=(a243+a149);
  a243=(a046*a243);
  a233=(a161*a233);
  a243=(a243-a233);
  a243=(a055*a243);
  a252=(a252+a243);
  if (res[0]!=0) res[0][40]=a252;
  a252=(a157*a026);
  a167=(a167*a026);
  a166=(a166*a167);
  a165=(a165*a166);
  a165=(a075*a165);
  a252=(a252-a165);
  a252=(a154*a252);
  a151=(a148*a151);
  a151=(a141*a151);
  a171=(a171*a151);
  a151=(a170*a171);
  a252=(a252+a151);
  a252=(a046*a252);
  a167=(a167/a056);
  a177=(a177*a167);
  a176=(a176*a177);
  a177=(a175*a176);
  a252=(a252+a177);
  a252=(a066*a252);
  if (res[0]!=0) res[0][41]=a252;
  a252=(a180*a026);
  a179=(a179*a166);
  a179=(a016*a179);
  a179=(a075*a179);
  a252=(a252-a179);
  a252=(a154*a252);
  a179=(a181*a171);
  a252=(a252+a179);
  a252=(a046*a252);
  a179=(a182*a176);
  a252=(a252+a179);
  a252=(a050*a252);
  a179=(a016*a171);
  a179=(a055*a179);
  a252=(a252-a179);
  a252=(-a252);
  if (res[0]!=0) res[0][42]=a252;
  a252=(a016*a171);
  a252=(a050*a252);
  a026=(a169*a026);
  a184=(a184*a166);
  a184=(a016*a184);
  a184=(a075*a184);
  a026=(a026-a184);
  a026=(a154*a026);
  a171=(a163*a171);
  a026=(a026+a171);
  a026=(a046*a026);
  a176=(a161*a176);
  a026=(a026+a176);
  a026=(a055*a026);
  a252=(a252+a026);
  if (res[0]!=0) res[0][43]=a252;
  a213=(a142*a213);
  a213=(a210*a213);
  a213=(a236*a213);
  a252=(a235*a213);
  a187=(a232*a187);
  a026=(a231*a187);
  a176=(a230*a026);
  a176=(a227*a176);
  a171=(a220*a229);
  a176=(a176+a171);
  a176=(a218*a176);
  a252=(a252-a176);
  a252=(a194*a252);
  a187=(a187/a056);
  a187=(a242*a187);
  a187=(a241*a187);
  a176=(a240*a187);
  a252=(a252+a176);
  a176=(a162*a252);
  a252=(a168*a252);
  a176=(a176-a252);
  a176=(-a176);
  if (res[0]!=0) res[0][44]=a176;
  if (res[0]!=0) res[0][45]=a252;
  a252=(a246*a213);
  a176=(a244*a026);
  a176=(a186*a176);
  a176=(a227*a176);
  a171=(a245*a229);
  a176=(a176+a171);
  a176=(a218*a176);
  a252=(a252-a176);
  a252=(a194*a252);
  a176=(a247*a187);
  a252=(a252+a176);
  a252=(a160*a252);
  a176=(a186*a213);
  a176=(a185*a176);
  a252=(a252-a176);
  a252=(-a252);
  if (res[0]!=0) res[0][46]=a252;
  a252=(a186*a213);
  a252=(a160*a252);
  a213=(a225*a213);
  a026=(a248*a026);
  a026=(a186*a026);
  a026=(a227*a026);
  a229=(a234*a229);
  a026=(a026+a229);
  a026=(a218*a026);
  a213=(a213-a026);
  a213=(a194*a213);
  a187=(a223*a187);
  a213=(a213+a187);
  a213=(a185*a213);
  a252=(a252+a213);
  if (res[0]!=0) res[0][47]=a252;
  a232=(a232*a189);
  a231=(a231*a232);
  a230=(a230*a231);
  a230=(a227*a230);
  a189=(a220*a228);
  a230=(a230+a189);
  a230=(a218*a230);
  a215=(a142*a215);
  a215=(a210*a215);
  a236=(a236*a215);
  a215=(a235*a236);
  a230=(a230+a215);
  a230=(a194*a230);
  a232=(a232/a056);
  a242=(a242*a232);
  a241=(a241*a242);
  a242=(a240*a241);
  a230=(a230-a242);
  a242=(a162*a230);
  a230=(a168*a230);
  a242=(a242-a230);
  a242=(-a242);
  if (res[0]!=0) res[0][48]=a242;
  if (res[0]!=0) res[0][49]=a230;
  a244=(a244*a231);
  a244=(a186*a244);
  a244=(a227*a244);
  a230=(a245*a228);
  a244=(a244+a230);
  a244=(a218*a244);
  a230=(a246*a236);
  a244=(a244+a230);
  a244=(a194*a244);
  a230=(a247*a241);
  a244=(a244-a230);
  a244=(a160*a244);
  a230=(a186*a236);
  a230=(a185*a230);
  a244=(a244-a230);
  a244=(-a244);
  if (res[0]!=0) res[0][50]=a244;
  a244=(a186*a236);
  a244=(a160*a244);
  a248=(a248*a231);
  a248=(a186*a248);
  a248=(a227*a248);
  a228=(a234*a228);
  a248=(a248+a228);
  a248=(a218*a248);
  a236=(a225*a236);
  a248=(a248+a236);
  a248=(a194*a248);
  a241=(a223*a241);
  a248=(a248-a241);
  a248=(a185*a248);
  a244=(a244+a248);
  if (res[0]!=0) res[0][51]=a244;
  a244=-1.;
  if (res[1]!=0) res[1][0]=a244;
  if (res[1]!=0) res[1][1]=a244;
  a244=(a105+a102);
  a244=(a244+a090);
  a248=(a019*a244);
  a248=(a053*a248);
  a241=(a035+a017);
  a241=(a241+a067);
  a236=(a006*a241);
  a236=(a053*a236);
  a248=(a248-a236);
  a236=(a038*a087);
  a236=(a236+a083);
  a083=(a069+a051);
  a228=(a038*a083);
  a236=(a236-a228);
  a228=(a038*a052);
  a231=(a030*a228);
  a236=(a236+a231);
  a231=(2.*a007);
  a230=(a038*a000);
  a231=(a231*a230);
  a236=(a236+a231);
  a231=(a028*a100);
  a231=(a231+a082);
  a082=(a069+a051);
  a242=(a028*a082);
  a231=(a231-a242);
  a242=(a028*a052);
  a232=(a004*a242);
  a231=(a231+a232);
  a232=(2.*a031);
  a215=(a028*a000);
  a232=(a232*a215);
  a231=(a231+a232);
  a232=(a236+a231);
  a189=(a001*a089);
  a189=(a189+a080);
  a080=(a069+a051);
  a252=(a001*a080);
  a189=(a189-a252);
  a252=(a001*a052);
  a213=(a011*a252);
  a187=(a008*a213);
  a189=(a189+a187);
  a187=(2.*a012);
  a026=(a001*a000);
  a187=(a187*a026);
  a189=(a189+a187);
  a232=(a232+a189);
  a187=(a006*a232);
  a248=(a248+a187);
  a187=(a058+a063);
  a229=(a038*a187);
  a176=(a038*a077);
  a176=(a176+a086);
  a229=(a229-a176);
  a176=(a039*a228);
  a229=(a229+a176);
  a176=(2.*a020);
  a176=(a176*a230);
  a229=(a229+a176);
  a176=(a058+a063);
  a230=(a028*a176);
  a086=(a028*a099);
  a086=(a086+a027);
  a230=(a230-a086);
  a086=(a042*a242);
  a230=(a230+a086);
  a086=(2.*a040);
  a086=(a086*a215);
  a230=(a230+a086);
  a086=(a229+a230);
  a215=(a058+a063);
  a027=(a001*a215);
  a171=(a001*a078);
  a171=(a171+a085);
  a027=(a027-a171);
  a171=(a021*a252);
  a085=(a008*a171);
  a027=(a027+a085);
  a085=(2.*a022);
  a085=(a085*a026);
  a027=(a027+a085);
  a086=(a086+a027);
  a085=(a019*a086);
  a248=(a248+a085);
  if (res[2]!=0) res[2][0]=a248;
  a248=(a118+a115);
  a119=(a119*a011);
  a248=(a248+a119);
  a085=(a019*a248);
  a085=(a053*a085);
  a026=(a037+a112);
  a123=(a123*a021);
  a026=(a026+a123);
  a184=(a006*a026);
  a184=(a053*a184);
  a085=(a085-a184);
  a184=(a038*a000);
  a166=(a030*a184);
  a179=(a028*a000);
  a177=(a004*a179);
  a167=(a166+a177);
  a151=(a001*a000);
  a165=(a011*a151);
  a243=(a008*a165);
  a167=(a167+a243);
  a233=(a006*a167);
  a085=(a085+a233);
  a233=(a039*a184);
  a149=(a042*a179);
  a071=(a233+a149);
  a239=(a021*a151);
  a251=(a008*a239);
  a071=(a071+a251);
  a224=(a019*a071);
  a085=(a085+a224);
  if (res[2]!=0) res[2][1]=a085;
  a085=(a038+a028);
  a085=(a085+a001);
  a224=(a019*a085);
  a224=(a053*a224);
  a257=(a038*a000);
  a253=(a028*a000);
  a237=(a257+a253);
  a255=(a001*a000);
  a237=(a237+a255);
  a250=(a006*a237);
  a224=(a224+a250);
  a224=(-a224);
  if (res[2]!=0) res[2][2]=a224;
  a224=(a038*a000);
  a250=(a028*a000);
  a049=(a224+a250);
  a249=(a001*a000);
  a049=(a049+a249);
  a238=(a019*a049);
  a222=(a038+a028);
  a222=(a222+a001);
  a113=(a006*a222);
  a113=(a053*a113);
  a238=(a238-a113);
  if (res[2]!=0) res[2][3]=a238;
  a238=(a038+a028);
  a238=(a238+a001);
  a113=(a019*a238);
  a113=(a053*a113);
  a221=(a038*a000);
  a256=(a028*a000);
  a254=(a221+a256);
  a258=(a001*a000);
  a254=(a254+a258);
  a259=(a006*a254);
  a113=(a113+a259);
  a113=(-a113);
  if (res[2]!=0) res[2][4]=a113;
  a113=(a038*a000);
  a259=(a028*a000);
  a260=(a113+a259);
  a261=(a001*a000);
  a260=(a260+a261);
  a262=(a019*a260);
  a263=(a038+a028);
  a263=(a263+a001);
  a264=(a006*a263);
  a264=(a053*a264);
  a262=(a262-a264);
  if (res[2]!=0) res[2][5]=a262;
  a025=(a025*a006);
  a015=(a015*a019);
  a025=(a025-a015);
  a015=(a019*a063);
  a262=(a060*a015);
  a025=(a025+a262);
  a262=(a006*a051);
  a264=(a060*a262);
  a025=(a025-a264);
  a264=casadi_sq(a060);
  a264=(a264*a000);
  a025=(a025+a264);
  if (res[2]!=0) res[2][6]=a025;
  a025=(a053*a019);
  a264=(a060*a025);
  a264=(a264+a079);
  a264=(a051-a264);
  a265=(a006*a000);
  a266=(a060*a265);
  a264=(a264-a266);
  if (res[2]!=0) res[2][7]=a264;
  a053=(a053*a006);
  a264=(a060*a053);
  a264=(a264+a084);
  a264=(a063-a264);
  a266=(a019*a000);
  a267=(a060*a266);
  a264=(a264+a267);
  if (res[2]!=0) res[2][8]=a264;
  if (res[2]!=0) res[2][9]=a000;
  a006=(a061*a006);
  a264=(a079*a006);
  a019=(a061*a019);
  a267=(a084*a019);
  a264=(a264-a267);
  a015=(a061*a015);
  a264=(a264+a015);
  a262=(a061*a262);
  a264=(a264-a262);
  a262=(2.*a060);
  a015=(a061*a000);
  a262=(a262*a015);
  a264=(a264+a262);
  if (res[2]!=0) res[2][10]=a264;
  a025=(a061*a025);
  a265=(a061*a265);
  a025=(a025+a265);
  a025=(-a025);
  if (res[2]!=0) res[2][11]=a025;
  a266=(a061*a266);
  a053=(a061*a053);
  a266=(a266-a053);
  if (res[2]!=0) res[2][12]=a266;
  a266=(a105+a102);
  a053=(a021*a266);
  a053=(a073*a053);
  a025=(a035+a017);
  a265=(a011*a025);
  a265=(a073*a265);
  a053=(a053-a265);
  a265=(a007*a228);
  a264=(a031*a242);
  a262=(a265+a264);
  a262=(a262+a236);
  a262=(a262+a231);
  a015=(a011*a262);
  a053=(a053+a015);
  a228=(a020*a228);
  a242=(a040*a242);
  a015=(a228+a242);
  a015=(a015+a229);
  a015=(a015+a230);
  a267=(a021*a015);
  a053=(a053+a267);
  if (res[2]!=0) res[2][13]=a053;
  a053=(a118+a115);
  a267=(a021*a053);
  a267=(a073*a267);
  a268=(a037+a112);
  a269=(a011*a268);
  a269=(a073*a269);
  a267=(a267-a269);
  a269=(a038*a087);
  a269=(a269+a116);
  a116=(a069+a051);
  a270=(a038*a116);
  a269=(a269-a270);
  a270=(2.*a030);
  a271=(a038*a052);
  a270=(a270*a271);
  a269=(a269+a270);
  a270=(a007*a184);
  a269=(a269+a270);
  a270=(a028*a100);
  a270=(a270+a114);
  a114=(a028*a116);
  a270=(a270-a114);
  a114=(2.*a004);
  a272=(a028*a052);
  a114=(a114*a272);
  a270=(a270+a114);
  a114=(a031*a179);
  a270=(a270+a114);
  a114=(a269+a270);
  a114=(a114+a166);
  a114=(a114+a177);
  a273=(a011*a114);
  a267=(a267+a273);
  a273=(a058+a063);
  a274=(a038*a273);
  a275=(a038*a077);
  a275=(a275+a047);
  a274=(a274-a275);
  a275=(2.*a039);
  a275=(a275*a271);
  a274=(a274+a275);
  a184=(a020*a184);
  a274=(a274+a184);
  a184=(a028*a273);
  a275=(a028*a099);
  a275=(a275+a117);
  a184=(a184-a275);
  a275=(2.*a042);
  a275=(a275*a272);
  a184=(a184+a275);
  a179=(a040*a179);
  a184=(a184+a179);
  a179=(a274+a184);
  a179=(a179+a233);
  a179=(a179+a149);
  a275=(a021*a179);
  a267=(a267+a275);
  if (res[2]!=0) res[2][14]=a267;
  a267=(a038+a028);
  a275=(a021*a267);
  a275=(a073*a275);
  a272=(a038*a052);
  a117=(a028*a052);
  a271=(a272+a117);
  a271=(a271+a257);
  a271=(a271+a253);
  a047=(a011*a271);
  a275=(a275+a047);
  a275=(-a275);
  if (res[2]!=0) res[2][15]=a275;
  a275=(a038*a052);
  a047=(a028*a052);
  a276=(a275+a047);
  a276=(a276+a224);
  a276=(a276+a250);
  a277=(a021*a276);
  a278=(a038+a028);
  a279=(a011*a278);
  a279=(a073*a279);
  a277=(a277-a279);
  if (res[2]!=0) res[2][16]=a277;
  a277=(a038+a028);
  a279=(a021*a277);
  a279=(a073*a279);
  a280=(a038*a052);
  a281=(a028*a052);
  a282=(a280+a281);
  a282=(a282+a221);
  a282=(a282+a256);
  a283=(a011*a282);
  a279=(a279+a283);
  a279=(-a279);
  if (res[2]!=0) res[2][17]=a279;
  a279=(a038*a052);
  a283=(a028*a052);
  a284=(a279+a283);
  a284=(a284+a113);
  a284=(a284+a259);
  a285=(a021*a284);
  a286=(a038+a028);
  a287=(a011*a286);
  a287=(a073*a287);
  a285=(a285-a287);
  if (res[2]!=0) res[2][18]=a285;
  a285=(a012*a089);
  a287=(a022*a078);
  a285=(a285-a287);
  a287=(a084*a022);
  a285=(a285-a287);
  a287=(a079*a012);
  a285=(a285+a287);
  a215=(a022*a215);
  a285=(a285+a215);
  a080=(a012*a080);
  a285=(a285-a080);
  a080=(a059*a021);
  a215=(a057*a011);
  a080=(a080+a215);
  a215=(a080*a052);
  a285=(a285+a215);
  a215=casadi_sq(a022);
  a287=casadi_sq(a012);
  a215=(a215+a287);
  a215=(a215*a000);
  a285=(a285+a215);
  if (res[2]!=0) res[2][19]=a285;
  a121=(a121*a011);
  a285=(a078*a021);
  a215=(a008*a285);
  a121=(a121-a215);
  a215=(a089*a011);
  a287=(a008*a215);
  a121=(a121+a287);
  a034=(a034*a021);
  a121=(a121-a034);
  a034=(a021*a273);
  a287=(a008*a034);
  a121=(a121+a287);
  a287=(a011*a116);
  a288=(a008*a287);
  a121=(a121-a288);
  a288=casadi_sq(a008);
  a288=(a288*a052);
  a121=(a121+a288);
  a080=(a080*a000);
  a121=(a121+a080);
  if (res[2]!=0) res[2][20]=a121;
  a121=(a089+a079);
  a121=(a069-a121);
  a121=(a121+a051);
  a080=(a011*a052);
  a288=(a008*a080);
  a121=(a121-a288);
  a288=(a012*a000);
  a121=(a121-a288);
  if (res[2]!=0) res[2][21]=a121;
  a121=(a078+a084);
  a121=(a058-a121);
  a121=(a121+a063);
  a288=(a021*a052);
  a289=(a008*a288);
  a121=(a121+a289);
  a289=(a022*a000);
  a121=(a121+a289);
  if (res[2]!=0) res[2][22]=a121;
  a121=(a069+a051);
  a089=(a089+a079);
  a089=(a121-a089);
  a289=(a011*a052);
  a290=(a008*a289);
  a089=(a089-a290);
  a290=(a012*a000);
  a089=(a089-a290);
  if (res[2]!=0) res[2][23]=a089;
  a089=(a058+a063);
  a078=(a078+a084);
  a078=(a089-a078);
  a290=(a021*a052);
  a291=(a008*a290);
  a078=(a078+a291);
  a291=(a022*a000);
  a078=(a078+a291);
  if (res[2]!=0) res[2][24]=a078;
  a078=(a052+a000);
  if (res[2]!=0) res[2][25]=a078;
  a078=(a052+a000);
  if (res[2]!=0) res[2][26]=a078;
  a078=(a021*a090);
  a078=(a073*a078);
  a291=(a011*a067);
  a291=(a073*a291);
  a078=(a078-a291);
  a213=(a012*a213);
  a078=(a078+a213);
  a171=(a022*a171);
  a078=(a078+a171);
  a171=(a011*a189);
  a078=(a078+a171);
  a171=(a021*a027);
  a078=(a078+a171);
  if (res[2]!=0) res[2][27]=a078;
  a078=(a001*a011);
  a171=(a079*a078);
  a285=(a001*a285);
  a171=(a171-a285);
  a215=(a001*a215);
  a171=(a171+a215);
  a215=(a001*a021);
  a285=(a084*a215);
  a171=(a171-a285);
  a034=(a001*a034);
  a171=(a171+a034);
  a287=(a001*a287);
  a171=(a171-a287);
  a287=(2.*a008);
  a034=(a001*a052);
  a287=(a287*a034);
  a171=(a171+a287);
  a287=(a021*a119);
  a287=(a073*a287);
  a171=(a171+a287);
  a287=(a011*a123);
  a287=(a073*a287);
  a171=(a171-a287);
  a165=(a012*a165);
  a171=(a171+a165);
  a239=(a022*a239);
  a171=(a171+a239);
  a239=(a011*a243);
  a171=(a171+a239);
  a239=(a021*a251);
  a171=(a171+a239);
  if (res[2]!=0) res[2][28]=a171;
  a080=(a001*a080);
  a171=(a021*a001);
  a171=(a073*a171);
  a080=(a080+a171);
  a171=(a011*a255);
  a080=(a080+a171);
  a080=(-a080);
  if (res[2]!=0) res[2][29]=a080;
  a288=(a001*a288);
  a080=(a011*a001);
  a080=(a073*a080);
  a288=(a288-a080);
  a080=(a021*a249);
  a288=(a288+a080);
  if (res[2]!=0) res[2][30]=a288;
  a289=(a001*a289);
  a288=(a021*a001);
  a288=(a073*a288);
  a289=(a289+a288);
  a288=(a011*a258);
  a289=(a289+a288);
  a289=(-a289);
  if (res[2]!=0) res[2][31]=a289;
  a290=(a001*a290);
  a011=(a011*a001);
  a011=(a073*a011);
  a290=(a290-a011);
  a021=(a021*a261);
  a290=(a290+a021);
  if (res[2]!=0) res[2][32]=a290;
  a290=(a041*a105);
  a290=(a073*a290);
  a021=(a010*a035);
  a021=(a073*a021);
  a290=(a290-a021);
  a265=(a265+a236);
  a236=(a010*a265);
  a290=(a290+a236);
  a228=(a228+a229);
  a229=(a041*a228);
  a290=(a290+a229);
  if (res[2]!=0) res[2][33]=a290;
  a290=(a041*a118);
  a290=(a073*a290);
  a229=(a010*a037);
  a229=(a073*a229);
  a290=(a290-a229);
  a269=(a269+a166);
  a166=(a010*a269);
  a290=(a290+a166);
  a274=(a274+a233);
  a233=(a041*a274);
  a290=(a290+a233);
  if (res[2]!=0) res[2][34]=a290;
  a290=(a041*a038);
  a290=(a073*a290);
  a272=(a272+a257);
  a257=(a010*a272);
  a290=(a290+a257);
  a290=(-a290);
  if (res[2]!=0) res[2][35]=a290;
  a275=(a275+a224);
  a224=(a041*a275);
  a290=(a010*a038);
  a290=(a073*a290);
  a224=(a224-a290);
  if (res[2]!=0) res[2][36]=a224;
  a224=(a041*a038);
  a224=(a073*a224);
  a280=(a280+a221);
  a221=(a010*a280);
  a224=(a224+a221);
  a224=(-a224);
  if (res[2]!=0) res[2][37]=a224;
  a279=(a279+a113);
  a113=(a041*a279);
  a224=(a010*a038);
  a224=(a073*a224);
  a113=(a113-a224);
  if (res[2]!=0) res[2][38]=a113;
  a113=(a031*a100);
  a224=(a040*a099);
  a113=(a113-a224);
  a224=(a084*a040);
  a113=(a113-a224);
  a224=(a079*a031);
  a113=(a113+a224);
  a176=(a040*a176);
  a113=(a113+a176);
  a082=(a031*a082);
  a113=(a113-a082);
  a082=(a042*a040);
  a176=(a004*a031);
  a082=(a082+a176);
  a176=(a082*a052);
  a113=(a113+a176);
  a176=casadi_sq(a040);
  a224=casadi_sq(a031);
  a176=(a176+a224);
  a176=(a176*a000);
  a113=(a113+a176);
  if (res[2]!=0) res[2][39]=a113;
  a113=(a004*a100);
  a176=(a042*a099);
  a113=(a113-a176);
  a176=(a084*a042);
  a113=(a113-a176);
  a176=(a079*a004);
  a113=(a113+a176);
  a176=(a042*a273);
  a113=(a113+a176);
  a176=(a004*a116);
  a113=(a113-a176);
  a176=casadi_sq(a042);
  a224=casadi_sq(a004);
  a176=(a176+a224);
  a176=(a176*a052);
  a113=(a113+a176);
  a082=(a082*a000);
  a113=(a113+a082);
  if (res[2]!=0) res[2][40]=a113;
  a113=(a100+a079);
  a113=(a069-a113);
  a113=(a113+a051);
  a082=(a004*a052);
  a113=(a113-a082);
  a082=(a031*a000);
  a113=(a113-a082);
  if (res[2]!=0) res[2][41]=a113;
  a113=(a099+a084);
  a113=(a058-a113);
  a113=(a113+a063);
  a082=(a042*a052);
  a113=(a113+a082);
  a082=(a040*a000);
  a113=(a113+a082);
  if (res[2]!=0) res[2][42]=a113;
  a100=(a100+a079);
  a100=(a121-a100);
  a113=(a004*a052);
  a100=(a100-a113);
  a113=(a031*a000);
  a100=(a100-a113);
  if (res[2]!=0) res[2][43]=a100;
  a099=(a099+a084);
  a099=(a089-a099);
  a100=(a042*a052);
  a099=(a099+a100);
  a100=(a040*a000);
  a099=(a099+a100);
  if (res[2]!=0) res[2][44]=a099;
  a099=(a052+a000);
  if (res[2]!=0) res[2][45]=a099;
  a099=(a052+a000);
  if (res[2]!=0) res[2][46]=a099;
  a099=(a041*a102);
  a099=(a073*a099);
  a100=(a010*a017);
  a100=(a073*a100);
  a099=(a099-a100);
  a264=(a264+a231);
  a231=(a010*a264);
  a099=(a099+a231);
  a242=(a242+a230);
  a230=(a041*a242);
  a099=(a099+a230);
  if (res[2]!=0) res[2][47]=a099;
  a099=(a041*a115);
  a099=(a073*a099);
  a230=(a010*a112);
  a230=(a073*a230);
  a099=(a099-a230);
  a270=(a270+a177);
  a177=(a010*a270);
  a099=(a099+a177);
  a184=(a184+a149);
  a149=(a041*a184);
  a099=(a099+a149);
  if (res[2]!=0) res[2][48]=a099;
  a099=(a041*a028);
  a099=(a073*a099);
  a117=(a117+a253);
  a253=(a010*a117);
  a099=(a099+a253);
  a099=(-a099);
  if (res[2]!=0) res[2][49]=a099;
  a047=(a047+a250);
  a250=(a041*a047);
  a099=(a010*a028);
  a099=(a073*a099);
  a250=(a250-a099);
  if (res[2]!=0) res[2][50]=a250;
  a250=(a041*a028);
  a250=(a073*a250);
  a281=(a281+a256);
  a256=(a010*a281);
  a250=(a250+a256);
  a250=(-a250);
  if (res[2]!=0) res[2][51]=a250;
  a283=(a283+a259);
  a041=(a041*a283);
  a010=(a010*a028);
  a073=(a073*a010);
  a041=(a041-a073);
  if (res[2]!=0) res[2][52]=a041;
  a041=(a007*a087);
  a073=(a020*a077);
  a041=(a041-a073);
  a073=(a084*a020);
  a041=(a041-a073);
  a073=(a079*a007);
  a041=(a041+a073);
  a187=(a020*a187);
  a041=(a041+a187);
  a083=(a007*a083);
  a041=(a041-a083);
  a083=(a039*a020);
  a187=(a030*a007);
  a083=(a083+a187);
  a187=(a083*a052);
  a041=(a041+a187);
  a187=casadi_sq(a020);
  a073=casadi_sq(a007);
  a187=(a187+a073);
  a187=(a187*a000);
  a041=(a041+a187);
  if (res[2]!=0) res[2][53]=a041;
  a041=(a030*a087);
  a187=(a039*a077);
  a041=(a041-a187);
  a187=(a084*a039);
  a041=(a041-a187);
  a187=(a079*a030);
  a041=(a041+a187);
  a187=(a039*a273);
  a041=(a041+a187);
  a187=(a030*a116);
  a041=(a041-a187);
  a187=casadi_sq(a039);
  a073=casadi_sq(a030);
  a187=(a187+a073);
  a187=(a187*a052);
  a041=(a041+a187);
  a083=(a083*a000);
  a041=(a041+a083);
  if (res[2]!=0) res[2][54]=a041;
  a041=(a087+a079);
  a069=(a069-a041);
  a069=(a069+a051);
  a041=(a030*a052);
  a069=(a069-a041);
  a041=(a007*a000);
  a069=(a069-a041);
  if (res[2]!=0) res[2][55]=a069;
  a069=(a077+a084);
  a058=(a058-a069);
  a058=(a058+a063);
  a069=(a039*a052);
  a058=(a058+a069);
  a069=(a020*a000);
  a058=(a058+a069);
  if (res[2]!=0) res[2][56]=a058;
  a087=(a087+a079);
  a121=(a121-a087);
  a087=(a030*a052);
  a121=(a121-a087);
  a087=(a007*a000);
  a121=(a121-a087);
  if (res[2]!=0) res[2][57]=a121;
  a077=(a077+a084);
  a089=(a089-a077);
  a077=(a039*a052);
  a089=(a089+a077);
  a077=(a020*a000);
  a089=(a089+a077);
  if (res[2]!=0) res[2][58]=a089;
  a006=(a060*a006);
  a007=(a038*a007);
  a006=(a006+a007);
  a031=(a028*a031);
  a006=(a006+a031);
  a012=(a001*a012);
  a006=(a006+a012);
  if (res[2]!=0) res[2][59]=a006;
  a078=(a008*a078);
  a030=(a038*a030);
  a078=(a078+a030);
  a004=(a028*a004);
  a078=(a078+a004);
  if (res[2]!=0) res[2][60]=a078;
  a078=(a038+a028);
  a078=(a078+a001);
  a078=(a078+a061);
  a078=(-a078);
  if (res[2]!=0) res[2][61]=a078;
  a078=(a038+a028);
  a078=(a078+a001);
  a078=(-a078);
  if (res[2]!=0) res[2][62]=a078;
  a060=(a060*a019);
  a020=(a038*a020);
  a060=(a060+a020);
  a040=(a028*a040);
  a060=(a060+a040);
  a022=(a001*a022);
  a060=(a060+a022);
  a060=(-a060);
  if (res[2]!=0) res[2][63]=a060;
  a215=(a008*a215);
  a039=(a038*a039);
  a215=(a215+a039);
  a042=(a028*a042);
  a215=(a215+a042);
  a215=(-a215);
  if (res[2]!=0) res[2][64]=a215;
  a215=(a038+a028);
  a215=(a215+a001);
  a215=(a215+a061);
  a215=(-a215);
  if (res[2]!=0) res[2][65]=a215;
  a215=(a038+a028);
  a215=(a215+a001);
  a215=(-a215);
  if (res[2]!=0) res[2][66]=a215;
  a215=cos(a003);
  a265=(a048*a265);
  a035=(a094*a035);
  a017=(a096*a017);
  a035=(a035+a017);
  a265=(a265-a035);
  a264=(a032*a264);
  a265=(a265+a264);
  a265=(a215*a265);
  a003=sin(a003);
  a105=(a045*a105);
  a102=(a101*a102);
  a105=(a105+a102);
  a228=(a048*a228);
  a105=(a105+a228);
  a242=(a032*a242);
  a105=(a105+a242);
  a105=(a003*a105);
  a265=(a265-a105);
  a105=cos(a009);
  a242=(a057*a252);
  a025=(a093*a025);
  a067=(a074*a067);
  a025=(a025+a067);
  a242=(a242-a025);
  a262=(a029*a262);
  a242=(a242+a262);
  a189=(a008*a189);
  a242=(a242+a189);
  a242=(a105*a242);
  a009=sin(a009);
  a266=(a097*a266);
  a090=(a088*a090);
  a266=(a266+a090);
  a252=(a059*a252);
  a266=(a266+a252);
  a015=(a029*a015);
  a266=(a266+a015);
  a027=(a008*a027);
  a266=(a266+a027);
  a266=(a009*a266);
  a242=(a242-a266);
  a242=(a265+a242);
  a266=cos(a005);
  a241=(a070*a241);
  a098=(a098-a241);
  a051=(a062*a051);
  a098=(a098-a051);
  a232=(a002*a232);
  a098=(a098+a232);
  a098=(a266*a098);
  a005=sin(a005);
  a244=(a081*a244);
  a244=(a244-a103);
  a063=(a068*a063);
  a244=(a244+a063);
  a086=(a002*a086);
  a244=(a244+a086);
  a244=(a005*a244);
  a098=(a098-a244);
  a242=(a242+a098);
  if (res[2]!=0) res[2][67]=a242;
  a269=(a048*a269);
  a037=(a094*a037);
  a112=(a096*a112);
  a037=(a037+a112);
  a269=(a269-a037);
  a270=(a032*a270);
  a269=(a269+a270);
  a269=(a215*a269);
  a118=(a045*a118);
  a115=(a101*a115);
  a118=(a118+a115);
  a274=(a048*a274);
  a118=(a118+a274);
  a184=(a032*a184);
  a118=(a118+a184);
  a118=(a003*a118);
  a269=(a269-a118);
  a122=(a122+a120);
  a116=(a108*a116);
  a122=(a122-a116);
  a268=(a093*a268);
  a122=(a122-a268);
  a123=(a074*a123);
  a122=(a122-a123);
  a057=(a057*a151);
  a122=(a122+a057);
  a114=(a029*a114);
  a122=(a122+a114);
  a243=(a008*a243);
  a122=(a122+a243);
  a122=(a105*a122);
  a273=(a111*a273);
  a125=(a125+a044);
  a273=(a273-a125);
  a053=(a097*a053);
  a273=(a273+a053);
  a119=(a088*a119);
  a273=(a273+a119);
  a059=(a059*a151);
  a273=(a273+a059);
  a179=(a029*a179);
  a273=(a273+a179);
  a251=(a008*a251);
  a273=(a273+a251);
  a273=(a009*a273);
  a122=(a122-a273);
  a122=(a269+a122);
  a167=(a002*a167);
  a026=(a070*a026);
  a167=(a167-a026);
  a167=(a266*a167);
  a248=(a081*a248);
  a071=(a002*a071);
  a248=(a248+a071);
  a248=(a005*a248);
  a167=(a167-a248);
  a122=(a122+a167);
  if (res[2]!=0) res[2][68]=a122;
  a122=(a045*a038);
  a167=(a101*a028);
  a122=(a122+a167);
  a122=(a003*a122);
  a272=(a048*a272);
  a117=(a032*a117);
  a272=(a272+a117);
  a272=(a215*a272);
  a122=(a122-a272);
  a267=(a097*a267);
  a272=(a088*a001);
  a267=(a267+a272);
  a267=(a009*a267);
  a272=(a108*a052);
  a271=(a029*a271);
  a272=(a272+a271);
  a255=(a008*a255);
  a272=(a272+a255);
  a272=(a105*a272);
  a267=(a267-a272);
  a267=(a122+a267);
  a085=(a081*a085);
  a124=(a124+a085);
  a124=(a005*a124);
  a062=(a062*a000);
  a237=(a002*a237);
  a062=(a062+a237);
  a062=(a266*a062);
  a124=(a124-a062);
  a267=(a267+a124);
  if (res[2]!=0) res[2][69]=a267;
  a267=(a094*a038);
  a124=(a096*a028);
  a267=(a267+a124);
  a267=(a215*a267);
  a275=(a048*a275);
  a047=(a032*a047);
  a275=(a275+a047);
  a275=(a003*a275);
  a267=(a267+a275);
  a278=(a093*a278);
  a275=(a074*a001);
  a278=(a278+a275);
  a278=(a105*a278);
  a275=(a111*a052);
  a276=(a029*a276);
  a275=(a275+a276);
  a249=(a008*a249);
  a275=(a275+a249);
  a275=(a009*a275);
  a278=(a278+a275);
  a278=(a267+a278);
  a222=(a070*a222);
  a024=(a024+a222);
  a024=(a266*a024);
  a068=(a068*a000);
  a049=(a002*a049);
  a068=(a068+a049);
  a068=(a005*a068);
  a024=(a024+a068);
  a278=(a278+a024);
  a278=(-a278);
  if (res[2]!=0) res[2][70]=a278;
  a045=(a045*a038);
  a101=(a101*a028);
  a045=(a045+a101);
  a045=(a003*a045);
  a280=(a048*a280);
  a281=(a032*a281);
  a280=(a280+a281);
  a280=(a215*a280);
  a045=(a045-a280);
  a097=(a097*a277);
  a088=(a088*a001);
  a097=(a097+a088);
  a097=(a009*a097);
  a108=(a108*a052);
  a282=(a029*a282);
  a108=(a108+a282);
  a258=(a008*a258);
  a108=(a108+a258);
  a108=(a105*a108);
  a097=(a097-a108);
  a097=(a045+a097);
  a081=(a081*a238);
  a081=(a005*a081);
  a254=(a002*a254);
  a254=(a266*a254);
  a081=(a081-a254);
  a097=(a097+a081);
  if (res[2]!=0) res[2][71]=a097;
  a094=(a094*a038);
  a096=(a096*a028);
  a094=(a094+a096);
  a215=(a215*a094);
  a048=(a048*a279);
  a032=(a032*a283);
  a048=(a048+a032);
  a003=(a003*a048);
  a215=(a215+a003);
  a093=(a093*a286);
  a074=(a074*a001);
  a093=(a093+a074);
  a105=(a105*a093);
  a111=(a111*a052);
  a029=(a029*a284);
  a111=(a111+a029);
  a008=(a008*a261);
  a111=(a111+a008);
  a009=(a009*a111);
  a105=(a105+a009);
  a105=(a215+a105);
  a070=(a070*a263);
  a266=(a266*a070);
  a002=(a002*a260);
  a005=(a005*a002);
  a266=(a266+a005);
  a105=(a105+a266);
  a105=(-a105);
  if (res[2]!=0) res[2][72]=a105;
  a105=(a064<=a153);
  a266=(a153<=a064);
  a266=(a266+a105);
  a105=(a105/a266);
  a266=(a046*a066);
  a005=(a170*a266);
  a005=(a105*a005);
  a002=(a152*a005);
  a260=(a140*a002);
  a070=(a260/a135);
  a070=(a036*a070);
  a127=(2.*a127);
  a070=(a070/a127);
  a263=(a070/a095);
  a009=(a066*a263);
  a111=(a064<=a137);
  a137=(a137<=a064);
  a137=(a137+a111);
  a111=(a111/a137);
  a137=(a139-a126);
  a137=pow(a138,a137);
  a137=(a139*a137);
  a002=(a128*a002);
  a008=(a137*a002);
  a008=(a111*a008);
  a091=(a091/a095);
  a070=(a091*a070);
  a261=(a008+a070);
  a009=(a009-a261);
  a104=(2.*a104);
  a261=(a014<=a076);
  a076=(a076<=a014);
  a076=(a261+a076);
  a261=(a261/a076);
  a136=(2.*a136);
  a076=(a008/a136);
  a054=pow(a054,a158);
  a054=(a109*a054);
  a005=(a141*a005);
  a014=(a148*a005);
  a029=(a023*a014);
  a029=(a050*a029);
  a014=(a110*a014);
  a014=(a055*a014);
  a029=(a029+a014);
  a266=(a154*a266);
  a014=(a157*a266);
  a284=casadi_sign(a075);
  a052=(a064<=a013);
  a093=(a013<=a064);
  a093=(a093+a052);
  a052=(a052/a093);
  a093=(a043<=a126);
  a043=(a126<=a043);
  a043=(a043+a093);
  a093=(a093/a043);
  a043=(a175*a066);
  a043=(a093*a043);
  a043=(a052*a043);
  a074=(a043/a056);
  a001=(a092<=a106);
  a106=(a106<=a092);
  a286=(a106+a001);
  a001=(a001/a286);
  a157=(a157/a156);
  a266=(a075*a266);
  a157=(a157*a266);
  a003=(a001*a157);
  a003=(a074-a003);
  a003=(a284*a003);
  a014=(a014+a003);
  a003=(a110*a014);
  a003=(a050*a003);
  a029=(a029-a003);
  a003=(a023*a014);
  a003=(a055*a003);
  a029=(a029+a003);
  a029=(a054*a029);
  a076=(a076+a029);
  a076=(a261*a076);
  a076=(a104*a076);
  a029=(a033*a076);
  a009=(a009+a029);
  if (res[2]!=0) res[2][73]=a009;
  a009=(a016*a055);
  a029=(a046*a050);
  a003=(a181*a029);
  a009=(a009-a003);
  a009=(a105*a009);
  a003=(a152*a009);
  a048=(a140*a003);
  a032=(a048/a135);
  a032=(a036*a032);
  a032=(a032/a127);
  a283=(a032/a095);
  a279=(a066*a283);
  a003=(a128*a003);
  a094=(a137*a003);
  a094=(a111*a094);
  a032=(a091*a032);
  a096=(a094+a032);
  a279=(a279-a096);
  a096=(a094/a136);
  a028=(a154*a055);
  a029=(a154*a029);
  a038=(a075*a029);
  a097=(a164*a038);
  a028=(a028-a097);
  a009=(a141*a009);
  a097=(a148*a009);
  a081=(a023*a097);
  a081=(a050*a081);
  a028=(a028+a081);
  a097=(a110*a097);
  a097=(a055*a097);
  a028=(a028+a097);
  a164=(a164/a156);
  a038=(a016*a038);
  a164=(a164*a038);
  a097=(a001*a164);
  a182=(a182*a050);
  a182=(a093*a182);
  a182=(a052*a182);
  a081=(a182/a056);
  a097=(a097-a081);
  a097=(a284*a097);
  a180=(a180*a029);
  a097=(a097-a180);
  a180=(a110*a097);
  a180=(a050*a180);
  a028=(a028-a180);
  a180=(a023*a097);
  a180=(a055*a180);
  a028=(a028+a180);
  a028=(a054*a028);
  a096=(a096+a028);
  a096=(a261*a096);
  a096=(a104*a096);
  a028=(a033*a096);
  a279=(a279+a028);
  if (res[2]!=0) res[2][74]=a279;
  a279=(a046*a055);
  a028=(a163*a279);
  a180=(a016*a050);
  a028=(a028+a180);
  a105=(a105*a028);
  a152=(a152*a105);
  a028=(a140*a152);
  a180=(a028/a135);
  a180=(a036*a180);
  a180=(a180/a127);
  a095=(a180/a095);
  a127=(a066*a095);
  a152=(a128*a152);
  a137=(a137*a152);
  a111=(a111*a137);
  a091=(a091*a180);
  a180=(a111+a091);
  a127=(a127-a180);
  a136=(a111/a136);
  a279=(a154*a279);
  a075=(a075*a279);
  a180=(a183*a075);
  a154=(a154*a050);
  a180=(a180+a154);
  a105=(a141*a105);
  a154=(a148*a105);
  a137=(a023*a154);
  a137=(a050*a137);
  a180=(a180+a137);
  a154=(a110*a154);
  a154=(a055*a154);
  a180=(a180+a154);
  a169=(a169*a279);
  a161=(a161*a055);
  a093=(a093*a161);
  a052=(a052*a093);
  a093=(a052/a056);
  a183=(a183/a156);
  a075=(a016*a075);
  a183=(a183*a075);
  a001=(a001*a183);
  a001=(a093-a001);
  a284=(a284*a001);
  a169=(a169+a284);
  a110=(a110*a169);
  a110=(a050*a110);
  a180=(a180-a110);
  a023=(a023*a169);
  a023=(a055*a023);
  a180=(a180+a023);
  a054=(a054*a180);
  a136=(a136+a054);
  a261=(a261*a136);
  a104=(a104*a261);
  a261=(a033*a104);
  a127=(a127+a261);
  if (res[2]!=0) res[2][75]=a127;
  a175=(a175*a046);
  a175=(a175+a008);
  a175=(a175+a070);
  a263=(a018*a263);
  a175=(a175+a263);
  a076=(a107*a076);
  a175=(a175+a076);
  a014=(a065*a014);
  a175=(a175+a014);
  if (res[2]!=0) res[2][76]=a175;
  a094=(a094+a032);
  a283=(a018*a283);
  a094=(a094+a283);
  a096=(a107*a096);
  a094=(a094+a096);
  a097=(a065*a097);
  a094=(a094+a097);
  if (res[2]!=0) res[2][77]=a094;
  a111=(a111+a091);
  a018=(a018*a095);
  a111=(a111+a018);
  a104=(a107*a104);
  a111=(a111+a104);
  a169=(a065*a169);
  a111=(a111+a169);
  if (res[2]!=0) res[2][78]=a111;
  a130=(a130/a131);
  a128=(a128/a135);
  a260=(a128*a260);
  a135=(a130*a260);
  if (res[2]!=0) res[2][79]=a135;
  a048=(a128*a048);
  a135=(a130*a048);
  if (res[2]!=0) res[2][80]=a135;
  a128=(a128*a028);
  a130=(a130*a128);
  if (res[2]!=0) res[2][81]=a130;
  a129=(2.*a129);
  a130=(a260/a131);
  a130=(a129*a130);
  if (res[2]!=0) res[2][82]=a130;
  a130=(a048/a131);
  a130=(a129*a130);
  if (res[2]!=0) res[2][83]=a130;
  a131=(a128/a131);
  a129=(a129*a131);
  if (res[2]!=0) res[2][84]=a129;
  a133=(a133/a134);
  a129=(a133*a260);
  if (res[2]!=0) res[2][85]=a129;
  a129=(a133*a048);
  if (res[2]!=0) res[2][86]=a129;
  a133=(a133*a128);
  if (res[2]!=0) res[2][87]=a133;
  a132=(2.*a132);
  a260=(a260/a134);
  a260=(a132*a260);
  if (res[2]!=0) res[2][88]=a260;
  a048=(a048/a134);
  a048=(a132*a048);
  if (res[2]!=0) res[2][89]=a048;
  a128=(a128/a134);
  a132=(a132*a128);
  if (res[2]!=0) res[2][90]=a132;
  a132=(a064<=a217);
  a128=(a217<=a064);
  a128=(a128+a132);
  a132=(a132/a128);
  a128=(a168-a162);
  a134=(a194*a128);
  a048=(a235*a134);
  a048=(a132*a048);
  a260=(a216*a048);
  a133=(a209*a260);
  a129=(a133/a205);
  a129=(a036*a129);
  a197=(2.*a197);
  a129=(a129/a197);
  a131=(a129/a196);
  a130=(a168*a131);
  a028=(a240*a194);
  a135=(a064<=a207);
  a207=(a207<=a064);
  a207=(a207+a135);
  a135=(a135/a207);
  a207=(a139-a126);
  a207=pow(a208,a207);
  a139=(a139*a207);
  a260=(a198*a260);
  a207=(a139*a260);
  a207=(a135*a207);
  a111=(a028+a207);
  a195=(a195/a196);
  a129=(a195*a129);
  a111=(a111+a129);
  a130=(a130-a111);
  a134=(a218*a134);
  a111=(a220*a134);
  a169=(a065*a111);
  a130=(a130-a169);
  a172=(2.*a172);
  a169=(a173<=a178);
  a178=(a178<=a173);
  a178=(a169+a178);
  a169=(a169/a178);
  a206=(2.*a206);
  a178=(a207/a206);
  a174=pow(a174,a158);
  a109=(a109*a174);
  a048=(a210*a048);
  a174=(a142*a048);
  a158=(a190*a174);
  a158=(a160*a158);
  a174=(a188*a174);
  a174=(a185*a174);
  a158=(a158+a174);
  a174=(a188*a111);
  a174=(a160*a174);
  a158=(a158-a174);
  a174=(a190*a111);
  a174=(a185*a174);
  a158=(a158+a174);
  a159=casadi_sign(a159);
  a174=(a064<=a192);
  a173=(a192<=a064);
  a173=(a173+a174);
  a174=(a174/a173);
  a173=(a193<=a126);
  a126=(a126<=a193);
  a126=(a126+a173);
  a173=(a173/a126);
  a128=(a240*a128);
  a128=(a173*a128);
  a128=(a174*a128);
  a126=(a128/a056);
  a193=(a092<=a191);
  a191=(a191<=a092);
  a092=(a191+a193);
  a193=(a193/a092);
  a104=(a220/a219);
  a134=(a227*a134);
  a018=(a104*a134);
  a095=(a193*a018);
  a095=(a126-a095);
  a095=(a159*a095);
  a091=(a190*a095);
  a091=(a185*a091);
  a158=(a158-a091);
  a091=(a188*a095);
  a091=(a160*a091);
  a158=(a158+a091);
  a158=(a109*a158);
  a178=(a178+a158);
  a178=(a169*a178);
  a178=(a172*a178);
  a158=(a033*a178);
  a130=(a130+a158);
  a158=(a065*a095);
  a130=(a130+a158);
  if (res[2]!=0) res[2][91]=a130;
  a130=(a194*a168);
  a158=(a235*a130);
  a158=(a132*a158);
  a091=(a216*a158);
  a094=(a209*a091);
  a097=(a094/a205);
  a097=(a036*a097);
  a097=(a097/a197);
  a096=(a097/a196);
  a283=(a168*a096);
  a091=(a198*a091);
  a032=(a139*a091);
  a032=(a135*a032);
  a097=(a195*a097);
  a175=(a032+a097);
  a283=(a283-a175);
  a130=(a218*a130);
  a220=(a220*a130);
  a175=(a065*a220);
  a283=(a283-a175);
  a175=(a032/a206);
  a158=(a210*a158);
  a014=(a142*a158);
  a076=(a190*a014);
  a076=(a160*a076);
  a014=(a188*a014);
  a014=(a185*a014);
  a076=(a076+a014);
  a014=(a188*a220);
  a014=(a160*a014);
  a076=(a076-a014);
  a014=(a190*a220);
  a014=(a185*a014);
  a076=(a076+a014);
  a240=(a240*a168);
  a240=(a173*a240);
  a240=(a174*a240);
  a014=(a240/a056);
  a130=(a227*a130);
  a104=(a104*a130);
  a263=(a193*a104);
  a263=(a014-a263);
  a263=(a159*a263);
  a070=(a190*a263);
  a070=(a185*a070);
  a076=(a076-a070);
  a070=(a188*a263);
  a070=(a160*a070);
  a076=(a076+a070);
  a076=(a109*a076);
  a175=(a175+a076);
  a175=(a169*a175);
  a175=(a172*a175);
  a076=(a033*a175);
  a283=(a283+a076);
  a076=(a065*a263);
  a283=(a283+a076);
  if (res[2]!=0) res[2][92]=a283;
  a283=(a186*a185);
  a076=(a194*a160);
  a070=(a246*a076);
  a283=(a283-a070);
  a283=(a132*a283);
  a070=(a216*a283);
  a008=(a209*a070);
  a127=(a008/a205);
  a127=(a036*a127);
  a127=(a127/a197);
  a261=(a127/a196);
  a136=(a168*a261);
  a070=(a198*a070);
  a054=(a139*a070);
  a054=(a135*a054);
  a127=(a195*a127);
  a180=(a054+a127);
  a136=(a136-a180);
  a076=(a218*a076);
  a245=(a245*a076);
  a180=(a065*a245);
  a136=(a136+a180);
  a180=(a054/a206);
  a023=(a218*a185);
  a076=(a227*a076);
  a110=(a226*a076);
  a023=(a023-a110);
  a283=(a210*a283);
  a110=(a142*a283);
  a284=(a190*a110);
  a284=(a160*a284);
  a023=(a023+a284);
  a110=(a188*a110);
  a110=(a185*a110);
  a023=(a023+a110);
  a110=(a188*a245);
  a110=(a160*a110);
  a023=(a023+a110);
  a110=(a190*a245);
  a110=(a185*a110);
  a023=(a023-a110);
  a226=(a226/a219);
  a076=(a186*a076);
  a226=(a226*a076);
  a110=(a193*a226);
  a247=(a247*a160);
  a247=(a173*a247);
  a247=(a174*a247);
  a284=(a247/a056);
  a110=(a110-a284);
  a110=(a159*a110);
  a001=(a190*a110);
  a001=(a185*a001);
  a023=(a023-a001);
  a001=(a188*a110);
  a001=(a160*a001);
  a023=(a023+a001);
  a023=(a109*a023);
  a180=(a180+a023);
  a180=(a169*a180);
  a180=(a172*a180);
  a023=(a033*a180);
  a136=(a136+a023);
  a023=(a065*a110);
  a136=(a136+a023);
  if (res[2]!=0) res[2][93]=a136;
  a136=(a194*a185);
  a023=(a225*a136);
  a001=(a186*a160);
  a023=(a023+a001);
  a132=(a132*a023);
  a216=(a216*a132);
  a023=(a209*a216);
  a001=(a023/a205);
  a036=(a036*a001);
  a036=(a036/a197);
  a196=(a036/a196);
  a197=(a168*a196);
  a216=(a198*a216);
  a139=(a139*a216);
  a135=(a135*a139);
  a195=(a195*a036);
  a036=(a135+a195);
  a197=(a197-a036);
  a136=(a218*a136);
  a234=(a234*a136);
  a036=(a065*a234);
  a197=(a197-a036);
  a206=(a135/a206);
  a227=(a227*a136);
  a136=(a155*a227);
  a218=(a218*a160);
  a136=(a136+a218);
  a132=(a210*a132);
  a218=(a142*a132);
  a036=(a190*a218);
  a036=(a160*a036);
  a136=(a136+a036);
  a218=(a188*a218);
  a218=(a185*a218);
  a136=(a136+a218);
  a218=(a188*a234);
  a218=(a160*a218);
  a136=(a136-a218);
  a218=(a190*a234);
  a218=(a185*a218);
  a136=(a136+a218);
  a223=(a223*a185);
  a173=(a173*a223);
  a174=(a174*a173);
  a173=(a174/a056);
  a155=(a155/a219);
  a227=(a186*a227);
  a155=(a155*a227);
  a193=(a193*a155);
  a193=(a173-a193);
  a159=(a159*a193);
  a190=(a190*a159);
  a190=(a185*a190);
  a136=(a136-a190);
  a188=(a188*a159);
  a188=(a160*a188);
  a136=(a136+a188);
  a109=(a109*a136);
  a206=(a206+a109);
  a169=(a169*a206);
  a172=(a172*a169);
  a033=(a033*a172);
  a197=(a197+a033);
  a065=(a065*a159);
  a197=(a197+a065);
  if (res[2]!=0) res[2][94]=a197;
  a207=(a028+a207);
  a207=(a207+a129);
  a131=(a162*a131);
  a207=(a207+a131);
  a111=(a072*a111);
  a207=(a207+a111);
  a178=(a107*a178);
  a207=(a207+a178);
  a095=(a072*a095);
  a207=(a207-a095);
  if (res[2]!=0) res[2][95]=a207;
  a028=(a028+a032);
  a028=(a028+a097);
  a096=(a162*a096);
  a028=(a028+a096);
  a220=(a072*a220);
  a028=(a028+a220);
  a175=(a107*a175);
  a028=(a028+a175);
  a263=(a072*a263);
  a028=(a028-a263);
  if (res[2]!=0) res[2][96]=a028;
  a054=(a054+a127);
  a261=(a162*a261);
  a054=(a054+a261);
  a245=(a072*a245);
  a054=(a054-a245);
  a180=(a107*a180);
  a054=(a054+a180);
  a110=(a072*a110);
  a054=(a054-a110);
  if (res[2]!=0) res[2][97]=a054;
  a135=(a135+a195);
  a196=(a162*a196);
  a135=(a135+a196);
  a234=(a072*a234);
  a135=(a135+a234);
  a107=(a107*a172);
  a135=(a135+a107);
  a072=(a072*a159);
  a135=(a135-a072);
  if (res[2]!=0) res[2][98]=a135;
  a200=(a200/a201);
  a198=(a198/a205);
  a133=(a198*a133);
  a205=(a200*a133);
  if (res[2]!=0) res[2][99]=a205;
  a094=(a198*a094);
  a205=(a200*a094);
  if (res[2]!=0) res[2][100]=a205;
  a008=(a198*a008);
  a205=(a200*a008);
  if (res[2]!=0) res[2][101]=a205;
  a198=(a198*a023);
  a200=(a200*a198);
  if (res[2]!=0) res[2][102]=a200;
  a199=(2.*a199);
  a200=(a133/a201);
  a200=(a199*a200);
  if (res[2]!=0) res[2][103]=a200;
  a200=(a094/a201);
  a200=(a199*a200);
  if (res[2]!=0) res[2][104]=a200;
  a200=(a008/a201);
  a200=(a199*a200);
  if (res[2]!=0) res[2][105]=a200;
  a201=(a198/a201);
  a199=(a199*a201);
  if (res[2]!=0) res[2][106]=a199;
  a203=(a203/a204);
  a199=(a203*a133);
  if (res[2]!=0) res[2][107]=a199;
  a199=(a203*a094);
  if (res[2]!=0) res[2][108]=a199;
  a199=(a203*a008);
  if (res[2]!=0) res[2][109]=a199;
  a203=(a203*a198);
  if (res[2]!=0) res[2][110]=a203;
  a202=(2.*a202);
  a133=(a133/a204);
  a133=(a202*a133);
  if (res[2]!=0) res[2][111]=a133;
  a094=(a094/a204);
  a094=(a202*a094);
  if (res[2]!=0) res[2][112]=a094;
  a008=(a008/a204);
  a008=(a202*a008);
  if (res[2]!=0) res[2][113]=a008;
  a198=(a198/a204);
  a202=(a202*a198);
  if (res[2]!=0) res[2][114]=a202;
  if (res[2]!=0) res[2][115]=a265;
  if (res[2]!=0) res[2][116]=a269;
  if (res[2]!=0) res[2][117]=a122;
  a267=(-a267);
  if (res[2]!=0) res[2][118]=a267;
  if (res[2]!=0) res[2][119]=a045;
  a215=(-a215);
  if (res[2]!=0) res[2][120]=a215;
  a208=log(a208);
  a208=(a208*a209);
  a260=(a208*a260);
  a138=log(a138);
  a138=(a138*a140);
  a002=(a138*a002);
  a260=(a260+a002);
  if (res[2]!=0) res[2][121]=a260;
  a091=(a208*a091);
  if (res[2]!=0) res[2][122]=a091;
  a003=(a138*a003);
  if (res[2]!=0) res[2][123]=a003;
  a138=(a138*a152);
  if (res[2]!=0) res[2][124]=a138;
  a070=(a208*a070);
  if (res[2]!=0) res[2][125]=a070;
  a208=(a208*a216);
  if (res[2]!=0) res[2][126]=a208;
  a144=(2.*a144);
  a048=(a214*a048);
  a208=(a048/a212);
  a005=(a150*a005);
  a216=(a005/a147);
  a208=(a208+a216);
  a208=(a143*a208);
  a208=(a144*a208);
  if (res[2]!=0) res[2][127]=a208;
  a158=(a214*a158);
  a208=(a158/a212);
  a208=(a143*a208);
  a208=(a144*a208);
  if (res[2]!=0) res[2][128]=a208;
  a009=(a150*a009);
  a208=(a009/a147);
  a208=(a143*a208);
  a208=(a144*a208);
  if (res[2]!=0) res[2][129]=a208;
  a105=(a150*a105);
  a208=(a105/a147);
  a208=(a143*a208);
  a208=(a144*a208);
  if (res[2]!=0) res[2][130]=a208;
  a283=(a214*a283);
  a208=(a283/a212);
  a208=(a143*a208);
  a208=(a144*a208);
  if (res[2]!=0) res[2][131]=a208;
  a132=(a214*a132);
  a208=(a132/a212);
  a143=(a143*a208);
  a144=(a144*a143);
  if (res[2]!=0) res[2][132]=a144;
  a144=(a211<=a146);
  a143=(a146<=a211);
  a143=(a143+a144);
  a144=(a144/a143);
  a143=(a142/a212);
  a048=(a143*a048);
  a048=(a144*a048);
  a208=(a145<=a146);
  a216=(a146<=a145);
  a216=(a216+a208);
  a208=(a208/a216);
  a216=(a148/a147);
  a005=(a216*a005);
  a005=(a208*a005);
  a048=(a048+a005);
  a048=(-a048);
  if (res[2]!=0) res[2][133]=a048;
  a158=(a143*a158);
  a158=(a144*a158);
  a158=(-a158);
  if (res[2]!=0) res[2][134]=a158;
  a009=(a216*a009);
  a009=(a208*a009);
  a009=(-a009);
  if (res[2]!=0) res[2][135]=a009;
  a216=(a216*a105);
  a208=(a208*a216);
  a208=(-a208);
  if (res[2]!=0) res[2][136]=a208;
  a283=(a143*a283);
  a283=(a144*a283);
  a283=(-a283);
  if (res[2]!=0) res[2][137]=a283;
  a143=(a143*a132);
  a144=(a144*a143);
  a144=(-a144);
  if (res[2]!=0) res[2][138]=a144;
  a134=(a134/a219);
  a266=(a266/a156);
  a134=(a134+a266);
  if (res[2]!=0) res[2][139]=a134;
  a130=(a130/a219);
  if (res[2]!=0) res[2][140]=a130;
  a038=(a038/a156);
  a038=(-a038);
  if (res[2]!=0) res[2][141]=a038;
  a075=(a075/a156);
  if (res[2]!=0) res[2][142]=a075;
  a076=(a076/a219);
  a076=(-a076);
  if (res[2]!=0) res[2][143]=a076;
  a227=(a227/a219);
  if (res[2]!=0) res[2][144]=a227;
  a192=(a192/a056);
  a128=(a192*a128);
  a013=(a013/a056);
  a043=(a013*a043);
  a128=(a128+a043);
  a191=(a191/a092);
  a018=(a191*a018);
  a126=(a126+a018);
  a126=(a128-a126);
  a126=(a126-a074);
  a106=(a106/a286);
  a157=(a106*a157);
  a126=(a126-a157);
  if (res[2]!=0) res[2][145]=a126;
  a240=(a192*a240);
  a104=(a191*a104);
  a014=(a014+a104);
  a014=(a240-a014);
  if (res[2]!=0) res[2][146]=a014;
  a182=(a013*a182);
  a081=(a081-a182);
  a164=(a106*a164);
  a081=(a081+a164);
  if (res[2]!=0) res[2][147]=a081;
  a013=(a013*a052);
  a093=(a013-a093);
  a106=(a106*a183);
  a093=(a093-a106);
  if (res[2]!=0) res[2][148]=a093;
  a226=(a191*a226);
  a284=(a284+a226);
  a247=(a192*a247);
  a284=(a284-a247);
  if (res[2]!=0) res[2][149]=a284;
  a192=(a192*a174);
  a191=(a191*a155);
  a173=(a173+a191);
  a173=(a192-a173);
  if (res[2]!=0) res[2][150]=a173;
  a128=(-a128);
  if (res[2]!=0) res[2][151]=a128;
  a240=(-a240);
  if (res[2]!=0) res[2][152]=a240;
  if (res[2]!=0) res[2][153]=a182;
  a013=(-a013);
  if (res[2]!=0) res[2][154]=a013;
  if (res[2]!=0) res[2][155]=a247;
  a192=(-a192);
  if (res[2]!=0) res[2][156]=a192;
  a192=(a064<=a153);
  a153=(a153<=a064);
  a153=(a153+a192);
  a192=(a192/a153);
  a148=(a148/a147);
  a147=(a146<=a145);
  a145=(a145<=a146);
  a145=(a147+a145);
  a147=(a147/a145);
  a148=(a148*a147);
  a150=(a150*a148);
  a141=(a141*a150);
  a192=(a192*a141);
  a170=(a170*a192);
  a170=(a046*a170);
  a066=(a066*a170);
  a066=(-a066);
  if (res[3]!=0) res[3][0]=a066;
  a066=(a016*a192);
  a066=(a055*a066);
  a181=(a181*a192);
  a181=(a046*a181);
  a181=(a050*a181);
  a066=(a066-a181);
  a066=(-a066);
  if (res[3]!=0) res[3][1]=a066;
  a016=(a016*a192);
  a050=(a050*a016);
  a163=(a163*a192);
  a046=(a046*a163);
  a055=(a055*a046);
  a050=(a050+a055);
  a050=(-a050);
  if (res[3]!=0) res[3][2]=a050;
  a050=(a064<=a217);
  a217=(a217<=a064);
  a217=(a217+a050);
  a050=(a050/a217);
  a142=(a142/a212);
  a212=(a146<=a211);
  a211=(a211<=a146);
  a211=(a212+a211);
  a212=(a212/a211);
  a142=(a142*a212);
  a214=(a214*a142);
  a210=(a210*a214);
  a050=(a050*a210);
  a235=(a235*a050);
  a235=(a194*a235);
  a168=(a168*a235);
  a162=(a162*a235);
  a162=(a168-a162);
  a162=(-a162);
  if (res[3]!=0) res[3][3]=a162;
  a168=(-a168);
  if (res[3]!=0) res[3][4]=a168;
  a168=(a186*a050);
  a168=(a185*a168);
  a246=(a246*a050);
  a246=(a194*a246);
  a246=(a160*a246);
  a168=(a168-a246);
  a168=(-a168);
  if (res[3]!=0) res[3][5]=a168;
  a186=(a186*a050);
  a160=(a160*a186);
  a225=(a225*a050);
  a194=(a194*a225);
  a185=(a185*a194);
  a160=(a160+a185);
  a160=(-a160);
  if (res[3]!=0) res[3][6]=a160;
  return 0;
}

/* jac_forward_dynamics:(x[12],tau[2],p[39],v_imp[2],out_xdot[12x1,0nz])->(jac_xdot_x[12x12,78nz],jac_xdot_tau[12x2,12nz],jac_xdot_p[12x39,234nz],jac_xdot_v_imp[12x2,12nz]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real **res1=res+4, *rr, *w00=w+292, *w01=w+298, *w02=w+304, *w03=w+316, *w05=w+318, *w07=w+320, *w08=w+356, *w09=w+408, *w10=w+410, *w11=w+567;
  casadi_real *w12=w+574, *w13=w+646, *w14=w+718, *w15=w+796, *w17=w+874, *w18=w+886, *w19=w+1120;
  const casadi_real **arg1=arg+5, *cs, *ss, *wr02, *wr04, *wr06;
  casadi_clear(w00, 6);
  casadi_fill(w01, 6, 1.);
  for (rr=w00+0, cs=w01; rr!=w00+6; rr+=1) *rr = *cs++;
  wr02 = arg[0] ? arg[0] : casadi_zeros;
  casadi_copy(arg[1], 2, w03);
  wr04 = arg[2] ? arg[2] : casadi_zeros;
  casadi_copy(arg[3], 2, w05);
  arg1[0]=wr02;
  arg1[1]=w03;
  arg1[2]=wr04;
  arg1[3]=w05;
  res1[0]=w01;
  if (casadi_f1(arg1, res1, iw, w, 0)) return 1;
  wr06 = wr02+0;
  arg1[0]=wr06;
  arg1[1]=wr04;
  res1[0]=w07;
  if (casadi_f0(arg1, res1, iw, w, 0)) return 1;
  rr = w01;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 1, casadi_s6, lt, d, casadi_s7, w);
  }
  arg1[0]=wr02;
  arg1[1]=w01;
  arg1[2]=w03;
  arg1[3]=wr04;
  arg1[4]=w05;
  res1[0]=w08;
  res1[1]=w09;
  res1[2]=w10;
  res1[3]=w11;
  if (casadi_f4(arg1, res1, iw, w, 0)) return 1;
  casadi_densify(w08, casadi_s8, w12, 0);
  rr = w12;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 12, casadi_s6, lt, d, casadi_s7, w);
  }
  for (i=0, rr=w12, cs=w12; i<72; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w13, cs=w12; i<12; ++i) for (j=0; j<6; ++j) rr[i+j*12] = *cs++;
  rr=w14;
  for (i=0, cs=w00; i<6; ++i) *rr++ = *cs++;
  for (i=0, cs=w13; i<72; ++i) *rr++ = *cs++;
  casadi_trans(w14,casadi_s10, w15, casadi_s9, iw);
  casadi_copy(w15, 78, res[0]);
  casadi_densify(w09, casadi_s11, w02, 0);
  rr = w02;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 2, casadi_s6, lt, d, casadi_s7, w);
  }
  for (i=0, rr=w02, cs=w02; i<12; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w17, cs=w02; i<2; ++i) for (j=0; j<6; ++j) rr[i+j*2] = *cs++;
  rr=w02;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  casadi_trans(w02,casadi_s13, w17, casadi_s12, iw);
  casadi_copy(w17, 12, res[1]);
  casadi_densify(w10, casadi_s14, w18, 0);
  rr = w18;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 39, casadi_s6, lt, d, casadi_s7, w);
  }
  for (i=0, rr=w18, cs=w18; i<234; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w19, cs=w18; i<39; ++i) for (j=0; j<6; ++j) rr[i+j*39] = *cs++;
  rr=w18;
  for (i=0, cs=w19; i<234; ++i) *rr++ = *cs++;
  casadi_trans(w18,casadi_s16, w19, casadi_s15, iw);
  casadi_copy(w19, 234, res[2]);
  casadi_densify(w11, casadi_s17, w17, 0);
  rr = w17;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 2, casadi_s6, lt, d, casadi_s7, w);
  }
  for (i=0, rr=w17, cs=w17; i<12; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w02, cs=w17; i<2; ++i) for (j=0; j<6; ++j) rr[i+j*2] = *cs++;
  rr=w17;
  for (i=0, cs=w02; i<12; ++i) *rr++ = *cs++;
  casadi_trans(w17,casadi_s13, w02, casadi_s12, iw);
  casadi_copy(w02, 12, res[3]);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f3(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_incref(void) {
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int jac_forward_dynamics_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int jac_forward_dynamics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real jac_forward_dynamics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jac_forward_dynamics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau";
    case 2: return "p";
    case 3: return "v_imp";
    case 4: return "out_xdot";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jac_forward_dynamics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "jac_xdot_x";
    case 1: return "jac_xdot_tau";
    case 2: return "jac_xdot_p";
    case 3: return "jac_xdot_v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_forward_dynamics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    case 2: return casadi_s1;
    case 3: return casadi_s4;
    case 4: return casadi_s18;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_forward_dynamics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s9;
    case 1: return casadi_s12;
    case 2: return casadi_s15;
    case 3: return casadi_s12;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 10;
  if (sz_res) *sz_res = 8;
  if (sz_iw) *sz_iw = 40;
  if (sz_w) *sz_w = 1354;
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 10*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 8*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 40*sizeof(casadi_int);
  if (sz_w) *sz_w = 1354*sizeof(casadi_real);
  return 0;
}

/* contact:(x[12],p[39],v_imp[2])->(delta[2],delta_dot[2],v_t[2],f_n[2],f_t[2],f_x[2],f_y[2]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25;
  a00=arg[1]? arg[1][21] : 0;
  a01=-9.9999999999999995e-07;
  a02=(a01*a00);
  a03=9.9999999999999995e-07;
  a04=arg[1]? arg[1][20] : 0;
  a05=(a03*a04);
  a02=(a02+a05);
  a02=casadi_sq(a02);
  a05=arg[0]? arg[0][2] : 0;
  a06=casadi_sq(a05);
  a07=arg[0]? arg[0][3] : 0;
  a08=casadi_sq(a07);
  a06=(a06+a08);
  a02=casadi_fmax(a02,a06);
  a06=sqrt(a02);
  a06=(a00+a06);
  a06=(a06-a04);
  if (res[0]!=0) res[0][0]=a06;
  a08=arg[1]? arg[1][27] : 0;
  a01=(a01*a08);
  a09=arg[1]? arg[1][26] : 0;
  a03=(a03*a09);
  a01=(a01+a03);
  a01=casadi_sq(a01);
  a03=arg[0]? arg[0][4] : 0;
  a10=casadi_sq(a03);
  a11=arg[0]? arg[0][5] : 0;
  a12=casadi_sq(a11);
  a10=(a10+a12);
  a01=casadi_fmax(a01,a10);
  a10=sqrt(a01);
  a10=(a08+a10);
  a10=(a10-a09);
  if (res[0]!=0) res[0][1]=a10;
  a12=-5.0000000000000000e-01;
  a02=pow(a02,a12);
  a13=(a02*a05);
  a14=arg[0]? arg[0][8] : 0;
  a13=(a13*a14);
  a15=(a02*a07);
  a16=arg[0]? arg[0][9] : 0;
  a15=(a15*a16);
  a13=(a13+a15);
  if (res[1]!=0) res[1][0]=a13;
  a01=pow(a01,a12);
  a12=(a01*a03);
  a15=arg[0]? arg[0][10] : 0;
  a12=(a12*a15);
  a17=(a01*a11);
  a18=arg[0]? arg[0][11] : 0;
  a17=(a17*a18);
  a12=(a12+a17);
  if (res[1]!=0) res[1][1]=a12;
  a17=arg[0]? arg[0][6] : 0;
  a19=(a00*a17);
  a20=(a02*a05);
  a20=(a20*a16);
  a19=(a19+a20);
  a20=(a02*a07);
  a20=(a20*a14);
  a19=(a19-a20);
  if (res[2]!=0) res[2][0]=a19;
  a20=arg[0]? arg[0][7] : 0;
  a20=(a17+a20);
  a14=(a08*a20);
  a16=(a09*a17);
  a14=(a14-a16);
  a16=(a01*a03);
  a16=(a16*a18);
  a14=(a14+a16);
  a16=(a01*a11);
  a16=(a16*a15);
  a14=(a14-a16);
  if (res[2]!=0) res[2][1]=a14;
  a16=0.;
  a21=1.3333333333333333e+00;
  a22=(a04*a00);
  a04=(a04-a00);
  a22=(a22/a04);
  a22=sqrt(a22);
  a22=(a21*a22);
  a04=1.;
  a00=arg[1]? arg[1][23] : 0;
  a00=casadi_sq(a00);
  a00=(a04-a00);
  a23=arg[1]? arg[1][22] : 0;
  a00=(a00/a23);
  a23=arg[1]? arg[1][25] : 0;
  a23=casadi_sq(a23);
  a23=(a04-a23);
  a24=arg[1]? arg[1][24] : 0;
  a23=(a23/a24);
  a00=(a00+a23);
  a22=(a22/a00);
  a06=casadi_fmax(a16,a06);
  a00=arg[1]? arg[1][33] : 0;
  a06=pow(a06,a00);
  a22=(a22*a06);
  a06=7.5000000000000000e-01;
  a23=-7.5000000000000000e-01;
  a24=arg[1]? arg[1][34] : 0;
  a24=casadi_sq(a24);
  a23=(a23*a24);
  a06=(a06+a23);
  a23=arg[2]? arg[2][0] : 0;
  a24=arg[1]? arg[1][35] : 0;
  a23=casadi_fmax(a23,a24);
  a23=(a06/a23);
  a23=(a23*a13);
  a23=(a04+a23);
  a22=(a22*a23);
  a22=casadi_fmax(a16,a22);
  if (res[3]!=0) res[3][0]=a22;
  a23=(a09*a08);
  a13=(a09-a08);
  a23=(a23/a13);
  a23=sqrt(a23);
  a21=(a21*a23);
  a23=arg[1]? arg[1][29] : 0;
  a23=casadi_sq(a23);
  a23=(a04-a23);
  a13=arg[1]? arg[1][28] : 0;
  a23=(a23/a13);
  a13=arg[1]? arg[1][31] : 0;
  a13=casadi_sq(a13);
  a13=(a04-a13);
  a25=arg[1]? arg[1][30] : 0;
  a13=(a13/a25);
  a23=(a23+a13);
  a21=(a21/a23);
  a10=casadi_fmax(a16,a10);
  a10=pow(a10,a00);
  a21=(a21*a10);
  a10=arg[2]? arg[2][1] : 0;
  a10=casadi_fmax(a10,a24);
  a06=(a06/a10);
  a06=(a06*a12);
  a06=(a04+a06);
  a21=(a21*a06);
  a21=casadi_fmax(a16,a21);
  if (res[3]!=0) res[3][1]=a21;
  a06=arg[1]? arg[1][36] : 0;
  a12=arg[1]? arg[1][37] : 0;
  a10=casadi_fabs(a19);
  a24=casadi_fmax(a12,a10);
  a00=(a06/a24);
  a00=(a00*a19);
  a00=(a00*a22);
  a10=(a10-a12);
  a23=arg[1]? arg[1][38] : 0;
  a23=(a23-a12);
  a10=(a10/a23);
  a10=casadi_fmax(a16,a10);
  a10=casadi_fmin(a04,a10);
  a00=(a00*a10);
  a00=(-a00);
  if (res[4]!=0) res[4][0]=a00;
  a09=(a09*a17);
  a08=(a08*a20);
  a09=(a09-a08);
  a08=(a01*a11);
  a08=(a08*a15);
  a09=(a09+a08);
  a08=(a01*a03);
  a08=(a08*a18);
  a09=(a09-a08);
  a09=casadi_fabs(a09);
  a08=casadi_fmax(a12,a09);
  a18=(a06/a08);
  a18=(a18*a14);
  a18=(a18*a21);
  a09=(a09-a12);
  a09=(a09/a23);
  a16=casadi_fmax(a16,a09);
  a04=casadi_fmin(a04,a16);
  a18=(a18*a04);
  a18=(-a18);
  if (res[4]!=0) res[4][1]=a18;
  a18=(a06/a24);
  a18=(a18*a02);
  a18=(a18*a19);
  a18=(a18*a22);
  a18=(a18*a10);
  a18=(a18*a07);
  a16=(a02*a22);
  a16=(a16*a05);
  a18=(a18-a16);
  if (res[5]!=0) res[5][0]=a18;
  a18=(a06/a08);
  a18=(a18*a01);
  a18=(a18*a14);
  a18=(a18*a21);
  a18=(a18*a04);
  a18=(a18*a11);
  a16=(a01*a21);
  a16=(a16*a03);
  a18=(a18-a16);
  if (res[5]!=0) res[5][1]=a18;
  a18=(a02*a22);
  a18=(a18*a07);
  a24=(a06/a24);
  a24=(a24*a02);
  a24=(a24*a19);
  a24=(a24*a22);
  a24=(a24*a10);
  a24=(a24*a05);
  a18=(a18+a24);
  a18=(-a18);
  if (res[6]!=0) res[6][0]=a18;
  a18=(a01*a21);
  a18=(a18*a11);
  a06=(a06/a08);
  a06=(a06*a01);
  a06=(a06*a14);
  a06=(a06*a21);
  a06=(a06*a04);
  a06=(a06*a03);
  a18=(a18+a06);
  a18=(-a18);
  if (res[6]!=0) res[6][1]=a18;
  return 0;
}

CASADI_SYMBOL_EXPORT int contact(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f5(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int contact_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void contact_release(int mem) {
}

CASADI_SYMBOL_EXPORT void contact_incref(void) {
}

CASADI_SYMBOL_EXPORT void contact_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int contact_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int contact_n_out(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_real contact_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* contact_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "p";
    case 2: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* contact_name_out(casadi_int i) {
  switch (i) {
    case 0: return "delta";
    case 1: return "delta_dot";
    case 2: return "v_t";
    case 3: return "f_n";
    case 4: return "f_t";
    case 5: return "f_x";
    case 6: return "f_y";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* contact_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s1;
    case 2: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* contact_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s4;
    case 2: return casadi_s4;
    case 3: return casadi_s4;
    case 4: return casadi_s4;
    case 5: return casadi_s4;
    case 6: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int contact_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 7;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int contact_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 7*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* energy:(x[12],p[39])->(kinetic,gravity,contact,total) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29;
  a00=5.0000000000000000e-01;
  a01=arg[1]? arg[1][6] : 0;
  a01=(a00*a01);
  a02=arg[0]? arg[0][6] : 0;
  a03=casadi_sq(a02);
  a01=(a01*a03);
  a03=arg[1]? arg[1][10] : 0;
  a03=(a00*a03);
  a04=arg[0]? arg[0][7] : 0;
  a04=(a02+a04);
  a05=casadi_sq(a04);
  a03=(a03*a05);
  a01=(a01+a03);
  a03=arg[1]? arg[1][14] : 0;
  a03=(a00*a03);
  a03=(a03*a05);
  a01=(a01+a03);
  a03=arg[1]? arg[1][5] : 0;
  a05=(a00*a03);
  a06=arg[1]? arg[1][7] : 0;
  a07=arg[1]? arg[1][19] : 0;
  a08=arg[0]? arg[0][0] : 0;
  a09=(a07+a08);
  a10=cos(a09);
  a11=(a06*a10);
  a11=(a11*a02);
  a12=arg[0]? arg[0][9] : 0;
  a11=(a11+a12);
  a11=casadi_sq(a11);
  a13=arg[0]? arg[0][8] : 0;
  a09=sin(a09);
  a14=(a06*a09);
  a14=(a14*a02);
  a14=(a13-a14);
  a14=casadi_sq(a14);
  a11=(a11+a14);
  a05=(a05*a11);
  a01=(a01+a05);
  a05=arg[1]? arg[1][9] : 0;
  a11=(a00*a05);
  a14=arg[1]? arg[1][4] : 0;
  a15=(a14*a10);
  a15=(a15*a02);
  a16=arg[1]? arg[1][11] : 0;
  a17=(a16*a04);
  a18=(a07+a08);
  a19=arg[0]? arg[0][1] : 0;
  a18=(a18+a19);
  a20=cos(a18);
  a17=(a17*a20);
  a17=(a15+a17);
  a17=(a17+a12);
  a21=arg[0]? arg[0][11] : 0;
  a17=(a17+a21);
  a17=casadi_sq(a17);
  a22=(a14*a09);
  a22=(a22*a02);
  a02=(a16*a04);
  a18=sin(a18);
  a02=(a02*a18);
  a02=(a22+a02);
  a02=(a13-a02);
  a23=arg[0]? arg[0][10] : 0;
  a02=(a02+a23);
  a02=casadi_sq(a02);
  a17=(a17+a02);
  a11=(a11*a17);
  a01=(a01+a11);
  a11=arg[1]? arg[1][13] : 0;
  a17=(a00*a11);
  a02=arg[1]? arg[1][8] : 0;
  a24=(a02*a04);
  a24=(a24*a20);
  a25=(a15+a24);
  a26=arg[1]? arg[1][15] : 0;
  a27=(a26*a04);
  a28=arg[1]? arg[1][32] : 0;
  a28=(a07+a28);
  a28=(a28+a08);
  a28=(a28+a19);
  a19=cos(a28);
  a27=(a27*a19);
  a25=(a25+a27);
  a25=(a25+a12);
  a25=(a25+a21);
  a25=casadi_sq(a25);
  a27=(a02*a04);
  a27=(a27*a18);
  a08=(a22+a27);
  a29=(a26*a04);
  a28=sin(a28);
  a29=(a29*a28);
  a08=(a08+a29);
  a08=(a13-a08);
  a08=(a08+a23);
  a08=casadi_sq(a08);
  a25=(a25+a08);
  a17=(a17*a25);
  a01=(a01+a17);
  a17=arg[1]? arg[1][16] : 0;
  a00=(a00*a17);
  a15=(a15+a24);
  a24=arg[1]? arg[1][12] : 0;
  a25=(a24*a04);
  a25=(a25*a19);
  a15=(a15+a25);
  a15=(a15+a12);
  a15=(a15+a21);
  a15=casadi_sq(a15);
  a22=(a22+a27);
  a04=(a24*a04);
  a04=(a04*a28);
  a22=(a22+a04);
  a13=(a13-a22);
  a13=(a13+a23);
  a13=casadi_sq(a13);
  a15=(a15+a13);
  a00=(a00*a15);
  a01=(a01+a00);
  if (res[0]!=0) res[0][0]=a01;
  a00=arg[1]? arg[1][1] : 0;
  a15=arg[1]? arg[1][3] : 0;
  a13=arg[1]? arg[1][17] : 0;
  a23=(a15*a13);
  a22=cos(a07);
  a23=(a23*a22);
  a04=arg[1]? arg[1][18] : 0;
  a15=(a15*a04);
  a07=sin(a07);
  a15=(a15*a07);
  a23=(a23+a15);
  a00=(a00*a23);
  a23=arg[1]? arg[1][0] : 0;
  a22=(a23*a22);
  a15=(a06*a10);
  a15=(a22+a15);
  a27=arg[0]? arg[0][2] : 0;
  a15=(a15+a27);
  a15=(a13*a15);
  a23=(a23*a07);
  a06=(a06*a09);
  a06=(a23+a06);
  a07=arg[0]? arg[0][3] : 0;
  a06=(a06+a07);
  a06=(a04*a06);
  a15=(a15+a06);
  a03=(a03*a15);
  a00=(a00+a03);
  a10=(a14*a10);
  a03=(a22+a10);
  a15=(a16*a20);
  a03=(a03+a15);
  a03=(a03+a27);
  a15=arg[0]? arg[0][4] : 0;
  a03=(a03+a15);
  a03=(a13*a03);
  a14=(a14*a09);
  a09=(a23+a14);
  a16=(a16*a18);
  a09=(a09+a16);
  a09=(a09+a07);
  a16=arg[0]? arg[0][5] : 0;
  a09=(a09+a16);
  a09=(a04*a09);
  a03=(a03+a09);
  a05=(a05*a03);
  a00=(a00+a05);
  a05=(a22+a10);
  a20=(a02*a20);
  a05=(a05+a20);
  a03=(a26*a19);
  a05=(a05+a03);
  a05=(a05+a27);
  a05=(a05+a15);
  a05=(a13*a05);
  a03=(a23+a14);
  a02=(a02*a18);
  a03=(a03+a02);
  a26=(a26*a28);
  a03=(a03+a26);
  a03=(a03+a07);
  a03=(a03+a16);
  a03=(a04*a03);
  a05=(a05+a03);
  a11=(a11*a05);
  a00=(a00+a11);
  a22=(a22+a10);
  a22=(a22+a20);
  a19=(a24*a19);
  a22=(a22+a19);
  a22=(a22+a27);
  a22=(a22+a15);
  a13=(a13*a22);
  a23=(a23+a14);
  a23=(a23+a02);
  a24=(a24*a28);
  a23=(a23+a24);
  a23=(a23+a07);
  a23=(a23+a16);
  a04=(a04*a23);
  a13=(a13+a04);
  a17=(a17*a13);
  a00=(a00+a17);
  a17=(-a00);
  if (res[1]!=0) res[1][0]=a17;
  a17=1.3333333333333333e+00;
  a13=arg[1]? arg[1][20] : 0;
  a04=arg[1]? arg[1][21] : 0;
  a23=(a13*a04);
  a24=(a13-a04);
  a23=(a23/a24);
  a23=sqrt(a23);
  a23=(a17*a23);
  a24=1.;
  a28=arg[1]? arg[1][33] : 0;
  a28=(a24+a28);
  a23=(a23/a28);
  a02=arg[1]? arg[1][23] : 0;
  a02=casadi_sq(a02);
  a02=(a24-a02);
  a14=arg[1]? arg[1][22] : 0;
  a02=(a02/a14);
  a14=arg[1]? arg[1][25] : 0;
  a14=casadi_sq(a14);
  a14=(a24-a14);
  a22=arg[1]? arg[1][24] : 0;
  a14=(a14/a22);
  a02=(a02+a14);
  a23=(a23/a02);
  a02=0.;
  a14=-9.9999999999999995e-07;
  a22=(a14*a04);
  a19=9.9999999999999995e-07;
  a20=(a19*a13);
  a22=(a22+a20);
  a22=casadi_sq(a22);
  a27=casadi_sq(a27);
  a07=casadi_sq(a07);
  a27=(a27+a07);
  a22=casadi_fmax(a22,a27);
  a22=sqrt(a22);
  a04=(a04+a22);
  a04=(a04-a13);
  a04=casadi_fmax(a02,a04);
  a04=pow(a04,a28);
  a23=(a23*a04);
  a04=arg[1]? arg[1][26] : 0;
  a13=arg[1]? arg[1][27] : 0;
  a22=(a04*a13);
  a27=(a04-a13);
  a22=(a22/a27);
  a22=sqrt(a22);
  a17=(a17*a22);
  a17=(a17/a28);
  a22=arg[1]? arg[1][29] : 0;
  a22=casadi_sq(a22);
  a22=(a24-a22);
  a27=arg[1]? arg[1][28] : 0;
  a22=(a22/a27);
  a27=arg[1]? arg[1][31] : 0;
  a27=casadi_sq(a27);
  a24=(a24-a27);
  a27=arg[1]? arg[1][30] : 0;
  a24=(a24/a27);
  a22=(a22+a24);
  a17=(a17/a22);
  a14=(a14*a13);
  a19=(a19*a04);
  a14=(a14+a19);
  a14=casadi_sq(a14);
  a15=casadi_sq(a15);
  a16=casadi_sq(a16);
  a15=(a15+a16);
  a14=casadi_fmax(a14,a15);
  a14=sqrt(a14);
  a13=(a13+a14);
  a13=(a13-a04);
  a02=casadi_fmax(a02,a13);
  a02=pow(a02,a28);
  a17=(a17*a02);
  a23=(a23+a17);
  if (res[2]!=0) res[2][0]=a23;
  a01=(a01-a00);
  a01=(a01+a23);
  if (res[3]!=0) res[3][0]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f6(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int energy_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void energy_release(int mem) {
}

CASADI_SYMBOL_EXPORT void energy_incref(void) {
}

CASADI_SYMBOL_EXPORT void energy_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int energy_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int energy_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real energy_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* energy_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "p";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* energy_name_out(casadi_int i) {
  switch (i) {
    case 0: return "kinetic";
    case 1: return "gravity";
    case 2: return "contact";
    case 3: return "total";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* energy_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* energy_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s19;
    case 1: return casadi_s19;
    case 2: return casadi_s19;
    case 3: return casadi_s19;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* end_effector:(x[12],udot[6],p[39])->(position[2],velocity[2],acceleration[2]) */
static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21;
  a00=arg[2]? arg[2][0] : 0;
  a01=arg[2]? arg[2][19] : 0;
  a02=cos(a01);
  a02=(a00*a02);
  a03=arg[2]? arg[2][4] : 0;
  a04=arg[0]? arg[0][0] : 0;
  a05=(a01+a04);
  a06=cos(a05);
  a06=(a03*a06);
  a02=(a02+a06);
  a06=arg[2]? arg[2][8] : 0;
  a07=(a01+a04);
  a08=arg[0]? arg[0][1] : 0;
  a07=(a07+a08);
  a09=cos(a07);
  a09=(a06*a09);
  a02=(a02+a09);
  a09=arg[2]? arg[2][12] : 0;
  a10=arg[2]? arg[2][32] : 0;
  a10=(a01+a10);
  a10=(a10+a04);
  a10=(a10+a08);
  a08=cos(a10);
  a08=(a09*a08);
  a02=(a02+a08);
  a08=arg[0]? arg[0][2] : 0;
  a02=(a02+a08);
  a08=arg[0]? arg[0][4] : 0;
  a02=(a02+a08);
  if (res[0]!=0) res[0][0]=a02;
  a01=sin(a01);
  a00=(a00*a01);
  a01=sin(a05);
  a01=(a03*a01);
  a00=(a00+a01);
  a01=sin(a07);
  a01=(a06*a01);
  a00=(a00+a01);
  a01=sin(a10);
  a01=(a09*a01);
  a00=(a00+a01);
  a01=arg[0]? arg[0][3] : 0;
  a00=(a00+a01);
  a01=arg[0]? arg[0][5] : 0;
  a00=(a00+a01);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[0]? arg[0][8] : 0;
  a01=sin(a05);
  a02=arg[0]? arg[0][6] : 0;
  a08=(a01*a02);
  a08=(a03*a08);
  a04=sin(a07);
  a11=arg[0]? arg[0][7] : 0;
  a12=(a02+a11);
  a13=(a04*a12);
  a13=(a06*a13);
  a08=(a08+a13);
  a13=sin(a10);
  a14=(a02+a11);
  a15=(a13*a14);
  a15=(a09*a15);
  a08=(a08+a15);
  a00=(a00-a08);
  a08=arg[0]? arg[0][10] : 0;
  a00=(a00+a08);
  if (res[1]!=0) res[1][0]=a00;
  a00=cos(a05);
  a08=(a00*a02);
  a08=(a03*a08);
  a15=cos(a07);
  a16=(a15*a12);
  a16=(a06*a16);
  a08=(a08+a16);
  a16=cos(a10);
  a17=(a16*a14);
  a17=(a09*a17);
  a08=(a08+a17);
  a17=arg[0]? arg[0][9] : 0;
  a08=(a08+a17);
  a17=arg[0]? arg[0][11] : 0;
  a08=(a08+a17);
  if (res[1]!=0) res[1][1]=a08;
  a08=arg[1]? arg[1][2] : 0;
  a17=cos(a05);
  a17=(a17*a02);
  a17=(a02*a17);
  a18=arg[1]? arg[1][0] : 0;
  a01=(a01*a18);
  a17=(a17+a01);
  a17=(a03*a17);
  a01=cos(a07);
  a19=(a02+a11);
  a01=(a01*a19);
  a01=(a12*a01);
  a20=arg[1]? arg[1][1] : 0;
  a21=(a18+a20);
  a04=(a04*a21);
  a01=(a01+a04);
  a01=(a06*a01);
  a17=(a17+a01);
  a01=cos(a10);
  a11=(a02+a11);
  a01=(a01*a11);
  a01=(a14*a01);
  a20=(a18+a20);
  a13=(a13*a20);
  a01=(a01+a13);
  a01=(a09*a01);
  a17=(a17+a01);
  a08=(a08-a17);
  a17=arg[1]? arg[1][4] : 0;
  a08=(a08+a17);
  if (res[2]!=0) res[2][0]=a08;
  a00=(a00*a18);
  a05=sin(a05);
  a05=(a05*a02);
  a02=(a02*a05);
  a00=(a00-a02);
  a03=(a03*a00);
  a15=(a15*a21);
  a07=sin(a07);
  a07=(a07*a19);
  a12=(a12*a07);
  a15=(a15-a12);
  a06=(a06*a15);
  a03=(a03+a06);
  a16=(a16*a20);
  a10=sin(a10);
  a10=(a10*a11);
  a14=(a14*a10);
  a16=(a16-a14);
  a09=(a09*a16);
  a03=(a03+a09);
  a09=arg[1]? arg[1][3] : 0;
  a03=(a03+a09);
  a09=arg[1]? arg[1][5] : 0;
  a03=(a03+a09);
  if (res[2]!=0) res[2][1]=a03;
  return 0;
}

CASADI_SYMBOL_EXPORT int end_effector(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f7(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int end_effector_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void end_effector_release(int mem) {
}

CASADI_SYMBOL_EXPORT void end_effector_incref(void) {
}

CASADI_SYMBOL_EXPORT void end_effector_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int end_effector_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int end_effector_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real end_effector_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* end_effector_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "udot";
    case 2: return "p";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* end_effector_name_out(casadi_int i) {
  switch (i) {
    case 0: return "position";
    case 1: return "velocity";
    case 2: return "acceleration";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* end_effector_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* end_effector_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s4;
    case 2: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int end_effector_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int end_effector_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


