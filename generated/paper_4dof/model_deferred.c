/* GENERATED FILE: DO NOT EDIT.
 * Regenerate: `jointplay derive robot.toml --out <this folder>`, or for the models
 * checked in under generated/: `pytest tests/test_generated.py --update-generated`.
 * model: paper_4dof
 * generator: jointplay.derive 0.1.0+f9f9f969bc7a, casadi 3.8.2, sympy 1.14.0
 * formulation: closed
 * input hash: df47f33855f1869f2982a497f6717424870174f4ae527b3380aa9d6fb9d8fdaa
 * The deferred part of this model: compiled on the first call that needs it,
 * linked against the library of model.c. Functions, in CasADi's calling
 * convention (their slots are forward_dynamics' and its Jacobian's):
 *   jac_forward_dynamics_inputs
 *   jac_forward_dynamics
 *   differentiable_forward_dynamics
 *   jac_differentiable_forward_dynamics
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) model_deferred_ ## ID
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
#define casadi_fabs CASADI_PREFIX(fabs)
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

casadi_real casadi_fmax(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x>y ? x : y;
#else
  return fmax(x, y);
#endif
}

casadi_real casadi_sq(casadi_real x) { return x*x;}

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

casadi_real casadi_sign(casadi_real x) { return x<0 ? -1 : x>0 ? 1 : x;}

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

void casadi_clear(casadi_real* x, casadi_int n) {
  casadi_int i;
  if (x) {
    for (i=0; i<n; ++i) *x++ = 0;
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
CASADI_SYMBOL_EXPORT void model_deferred_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int model_deferred_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int model_deferred_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[45] = 
  {6, 6, 0, 6, 12, 18, 24, 30,
  36, 0, 1, 2, 3, 4, 5, 0,
  1, 2, 3, 4, 5, 0, 1, 2,
  3, 4, 5, 0, 1, 2, 3, 4,
  5, 0, 1, 2, 3, 4, 5, 0,
  1, 2, 3, 4, 5};
static const casadi_int casadi_s1[24] = 
  {6, 6, 0, 0, 1, 3, 6, 10,
  15, 0, 0, 1, 0, 1, 2, 0,
  1, 2, 3, 0, 1, 2, 3, 4};
static const casadi_int casadi_s2[6] = {0, 1, 2, 3, 4, 5};
static const casadi_int casadi_s3[7] = {6, 2, 0, 1, 2, 0, 1};
static const casadi_int casadi_s4[17] = 
  {12, 2, 0, 6, 12, 6, 7, 8,
  9, 10, 11, 6, 7, 8, 9, 10,
  11};
static const casadi_int casadi_s5[27] = 
  {2, 12, 0, 0, 0, 0, 0, 0,
  0, 2, 4, 6, 8, 10, 12, 0,
  1, 0, 1, 0, 1, 0, 1, 0,
  1, 0, 1};
static const casadi_int casadi_s6[199] = 
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
static const casadi_int casadi_s7[276] = 
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
static const casadi_int casadi_s8[249] = 
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
static const casadi_int casadi_s9[12] = 
  {6, 2, 0, 3, 7, 0, 2, 3,
  0, 1, 4, 5};
static const casadi_int casadi_s10[3] = {12, 1, 1};
static const casadi_int casadi_s11[3] = {2, 1, 1};
static const casadi_int casadi_s12[3] = {39, 1, 1};

static const casadi_real casadi_zeros[39] = 
  {0.};

/* forcing:(x[12],tau[2],p[39],v_imp[2])->(f[6]) */
static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55;
  a00=arg[1]? arg[1][0] : 0;
  a01=arg[2]? arg[2][36] : 0;
  a02=arg[2]? arg[2][37] : 0;
  a03=1.0000000000000000e-03;
  a04=arg[2]? arg[2][38] : 0;
  a03=(a03*a04);
  a03=casadi_fmax(a02,a03);
  a05=arg[2]? arg[2][21] : 0;
  a06=arg[0]? arg[0][6] : 0;
  a07=(a05*a06);
  a08=-9.9999999999999995e-07;
  a09=(a08*a05);
  a10=9.9999999999999995e-07;
  a11=arg[2]? arg[2][20] : 0;
  a12=(a10*a11);
  a09=(a09+a12);
  a09=casadi_sq(a09);
  a12=arg[0]? arg[0][2] : 0;
  a13=casadi_sq(a12);
  a14=arg[0]? arg[0][3] : 0;
  a15=casadi_sq(a14);
  a13=(a13+a15);
  a09=casadi_fmax(a09,a13);
  a13=-5.0000000000000000e-01;
  a15=pow(a09,a13);
  a16=(a15*a12);
  a17=arg[0]? arg[0][9] : 0;
  a18=(a16*a17);
  a07=(a07+a18);
  a18=(a15*a14);
  a19=arg[0]? arg[0][8] : 0;
  a20=(a18*a19);
  a07=(a07-a20);
  a20=casadi_fabs(a07);
  a21=casadi_fmax(a03,a20);
  a22=(a01/a21);
  a22=(a22*a07);
  a23=0.;
  a09=sqrt(a09);
  a09=(a05+a09);
  a09=(a09-a11);
  a24=(a23<a09);
  a25=1.3333333333333333e+00;
  a26=(a11*a05);
  a11=(a11-a05);
  a26=(a26/a11);
  a26=sqrt(a26);
  a26=(a25*a26);
  a11=1.;
  a27=arg[2]? arg[2][23] : 0;
  a27=casadi_sq(a27);
  a27=(a11-a27);
  a28=arg[2]? arg[2][22] : 0;
  a27=(a27/a28);
  a28=arg[2]? arg[2][25] : 0;
  a28=casadi_sq(a28);
  a28=(a11-a28);
  a29=arg[2]? arg[2][24] : 0;
  a28=(a28/a29);
  a27=(a27+a28);
  a26=(a26/a27);
  a27=7.5000000000000000e-01;
  a28=-7.5000000000000000e-01;
  a29=arg[2]? arg[2][34] : 0;
  a29=casadi_sq(a29);
  a28=(a28*a29);
  a27=(a27+a28);
  a28=arg[3]? arg[3][0] : 0;
  a29=arg[2]? arg[2][35] : 0;
  a28=casadi_fmax(a28,a29);
  a28=(a27/a28);
  a16=(a16*a19);
  a18=(a18*a17);
  a16=(a16+a18);
  a28=(a28*a16);
  a28=(a11+a28);
  a26=(a26*a28);
  a28=1.0000000000000000e-300;
  a09=casadi_fmax(a28,a09);
  a16=arg[2]? arg[2][33] : 0;
  a09=pow(a09,a16);
  a26=(a26*a09);
  a24=(a24?a26:0);
  a24=casadi_fmax(a23,a24);
  a22=(a22*a24);
  a20=(a20-a02);
  a04=(a04-a02);
  a20=(a20/a04);
  a20=casadi_fmax(a23,a20);
  a20=casadi_fmin(a11,a20);
  a22=(a22*a20);
  a22=(a22*a05);
  a00=(a00-a22);
  a22=arg[2]? arg[2][26] : 0;
  a05=(a22*a06);
  a26=arg[2]? arg[2][27] : 0;
  a09=arg[0]? arg[0][7] : 0;
  a09=(a06+a09);
  a18=(a26*a09);
  a17=(a05-a18);
  a08=(a08*a26);
  a10=(a10*a22);
  a08=(a08+a10);
  a08=casadi_sq(a08);
  a10=arg[0]? arg[0][4] : 0;
  a19=casadi_sq(a10);
  a30=arg[0]? arg[0][5] : 0;
  a31=casadi_sq(a30);
  a19=(a19+a31);
  a08=casadi_fmax(a08,a19);
  a13=pow(a08,a13);
  a19=(a13*a30);
  a31=arg[0]? arg[0][10] : 0;
  a32=(a19*a31);
  a17=(a17+a32);
  a33=(a13*a10);
  a34=arg[0]? arg[0][11] : 0;
  a35=(a33*a34);
  a17=(a17-a35);
  a17=casadi_fabs(a17);
  a03=casadi_fmax(a03,a17);
  a36=(a01/a03);
  a18=(a18-a05);
  a18=(a18+a35);
  a18=(a18-a32);
  a36=(a36*a18);
  a08=sqrt(a08);
  a08=(a26+a08);
  a08=(a08-a22);
  a32=(a23<a08);
  a35=(a22*a26);
  a05=(a22-a26);
  a35=(a35/a05);
  a35=sqrt(a35);
  a25=(a25*a35);
  a35=arg[2]? arg[2][29] : 0;
  a35=casadi_sq(a35);
  a35=(a11-a35);
  a05=arg[2]? arg[2][28] : 0;
  a35=(a35/a05);
  a05=arg[2]? arg[2][31] : 0;
  a05=casadi_sq(a05);
  a05=(a11-a05);
  a37=arg[2]? arg[2][30] : 0;
  a05=(a05/a37);
  a35=(a35+a05);
  a25=(a25/a35);
  a35=arg[3]? arg[3][1] : 0;
  a35=casadi_fmax(a35,a29);
  a27=(a27/a35);
  a33=(a33*a31);
  a19=(a19*a34);
  a33=(a33+a19);
  a27=(a27*a33);
  a27=(a11+a27);
  a25=(a25*a27);
  a28=casadi_fmax(a28,a08);
  a28=pow(a28,a16);
  a25=(a25*a28);
  a32=(a32?a25:0);
  a32=casadi_fmax(a23,a32);
  a36=(a36*a32);
  a17=(a17-a02);
  a17=(a17/a04);
  a23=casadi_fmax(a23,a17);
  a11=casadi_fmin(a11,a23);
  a36=(a36*a11);
  a26=(a36*a26);
  a00=(a00-a26);
  a36=(a36*a22);
  a00=(a00+a36);
  a36=arg[2]? arg[2][17] : 0;
  a22=arg[2]? arg[2][9] : 0;
  a23=(a36*a22);
  a17=arg[2]? arg[2][4] : 0;
  a04=arg[2]? arg[2][19] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a25=(a04+a02);
  a28=sin(a25);
  a16=(a17*a28);
  a08=arg[2]? arg[2][11] : 0;
  a27=arg[0]? arg[0][1] : 0;
  a33=(a25+a27);
  a19=sin(a33);
  a34=(a08*a19);
  a34=(a16+a34);
  a31=(a23*a34);
  a00=(a00-a31);
  a31=arg[2]? arg[2][13] : 0;
  a35=(a36*a31);
  a29=arg[2]? arg[2][8] : 0;
  a05=(a29*a19);
  a16=(a16+a05);
  a37=arg[2]? arg[2][15] : 0;
  a38=arg[2]? arg[2][32] : 0;
  a04=(a04+a38);
  a04=(a04+a02);
  a04=(a04+a27);
  a27=sin(a04);
  a02=(a37*a27);
  a38=(a16+a02);
  a39=(a35*a38);
  a00=(a00-a39);
  a39=arg[2]? arg[2][16] : 0;
  a40=(a36*a39);
  a41=arg[2]? arg[2][12] : 0;
  a42=(a41*a27);
  a16=(a16+a42);
  a43=(a40*a16);
  a00=(a00-a43);
  a43=arg[2]? arg[2][18] : 0;
  a44=(a43*a22);
  a25=cos(a25);
  a45=(a17*a25);
  a33=cos(a33);
  a46=(a08*a33);
  a46=(a45+a46);
  a47=(a44*a46);
  a00=(a00+a47);
  a47=(a43*a31);
  a48=(a29*a33);
  a45=(a45+a48);
  a04=cos(a04);
  a49=(a37*a04);
  a50=(a45+a49);
  a51=(a47*a50);
  a00=(a00+a51);
  a51=(a43*a39);
  a52=(a41*a04);
  a45=(a45+a52);
  a53=(a51*a45);
  a00=(a00+a53);
  a46=(a22*a46);
  a06=casadi_sq(a06);
  a17=(a17*a06);
  a53=(a17*a28);
  a09=casadi_sq(a09);
  a54=(a08*a09);
  a55=(a54*a19);
  a55=(a53+a55);
  a46=(a46*a55);
  a00=(a00+a46);
  a34=(a22*a34);
  a17=(a17*a25);
  a54=(a54*a33);
  a54=(a17+a54);
  a34=(a34*a54);
  a00=(a00-a34);
  a50=(a31*a50);
  a29=(a29*a09);
  a34=(a29*a19);
  a53=(a53+a34);
  a37=(a37*a09);
  a34=(a37*a27);
  a34=(a53+a34);
  a50=(a50*a34);
  a00=(a00+a50);
  a38=(a31*a38);
  a29=(a29*a33);
  a17=(a17+a29);
  a37=(a37*a04);
  a37=(a17+a37);
  a38=(a38*a37);
  a00=(a00-a38);
  a45=(a39*a45);
  a41=(a41*a09);
  a27=(a41*a27);
  a53=(a53+a27);
  a45=(a45*a53);
  a00=(a00+a45);
  a16=(a39*a16);
  a41=(a41*a04);
  a17=(a17+a41);
  a16=(a16*a17);
  a00=(a00-a16);
  a16=arg[2]? arg[2][7] : 0;
  a41=(a16*a43);
  a04=arg[2]? arg[2][5] : 0;
  a41=(a41*a04);
  a41=(a41*a25);
  a00=(a00+a41);
  a41=(a16*a36);
  a41=(a41*a04);
  a41=(a41*a28);
  a00=(a00-a41);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[1]? arg[1][1] : 0;
  a00=(a00-a26);
  a02=(a05+a02);
  a26=(a35*a02);
  a00=(a00-a26);
  a05=(a05+a42);
  a42=(a40*a05);
  a00=(a00-a42);
  a49=(a48+a49);
  a42=(a47*a49);
  a00=(a00+a42);
  a48=(a48+a52);
  a52=(a51*a48);
  a00=(a00+a52);
  a49=(a31*a49);
  a49=(a49*a34);
  a00=(a00+a49);
  a02=(a31*a02);
  a02=(a02*a37);
  a00=(a00-a02);
  a48=(a39*a48);
  a48=(a48*a53);
  a00=(a00+a48);
  a05=(a39*a05);
  a05=(a05*a17);
  a00=(a00-a05);
  a05=(a08*a43);
  a05=(a05*a22);
  a05=(a05*a33);
  a00=(a00+a05);
  a05=(a08*a22);
  a48=(a05*a54);
  a48=(a48*a19);
  a00=(a00-a48);
  a08=(a08*a36);
  a08=(a08*a22);
  a08=(a08*a19);
  a00=(a00-a08);
  a05=(a05*a55);
  a05=(a05*a33);
  a00=(a00+a05);
  if (res[0]!=0) res[0][1]=a00;
  a00=(a01*a15);
  a00=(a00/a21);
  a00=(a00*a07);
  a00=(a00*a24);
  a00=(a00*a20);
  a20=(a00*a14);
  a15=(a15*a24);
  a24=(a15*a12);
  a20=(a20-a24);
  a36=(a36*a04);
  a20=(a20+a36);
  a20=(a20+a23);
  a20=(a20+a35);
  a20=(a20+a40);
  a54=(a22*a54);
  a20=(a20+a54);
  a37=(a31*a37);
  a20=(a20+a37);
  a17=(a39*a17);
  a20=(a20+a17);
  a16=(a16*a04);
  a16=(a16*a06);
  a25=(a16*a25);
  a20=(a20+a25);
  if (res[0]!=0) res[0][2]=a20;
  a43=(a43*a04);
  a15=(a15*a14);
  a00=(a00*a12);
  a15=(a15+a00);
  a43=(a43-a15);
  a43=(a43+a44);
  a43=(a43+a47);
  a43=(a43+a51);
  a22=(a22*a55);
  a43=(a43+a22);
  a31=(a31*a34);
  a43=(a43+a31);
  a39=(a39*a53);
  a43=(a43+a39);
  a16=(a16*a28);
  a43=(a43+a16);
  if (res[0]!=0) res[0][3]=a43;
  a01=(a01*a13);
  a01=(a01/a03);
  a01=(a01*a18);
  a01=(a01*a32);
  a01=(a01*a11);
  a11=(a01*a30);
  a13=(a13*a32);
  a32=(a13*a10);
  a11=(a11-a32);
  a11=(a11+a23);
  a11=(a11+a35);
  a11=(a11+a40);
  a11=(a11+a54);
  a11=(a11+a37);
  a11=(a11+a17);
  if (res[0]!=0) res[0][4]=a11;
  a13=(a13*a30);
  a01=(a01*a10);
  a13=(a13+a01);
  a44=(a44-a13);
  a44=(a44+a47);
  a44=(a44+a51);
  a44=(a44+a22);
  a44=(a44+a31);
  a44=(a44+a39);
  if (res[0]!=0) res[0][5]=a44;
  return 0;
}

/* mass_matrix:(q[6],p[39])->(M[6x6]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  a13=arg[0]? arg[0][1] : 0;
  a14=(a09+a13);
  a15=cos(a14);
  a16=(a12*a15);
  a16=(a11+a16);
  a17=casadi_sq(a16);
  a09=sin(a09);
  a06=(a06*a09);
  a14=sin(a14);
  a18=(a12*a14);
  a18=(a06+a18);
  a19=casadi_sq(a18);
  a17=(a17+a19);
  a17=(a05*a17);
  a00=(a00+a17);
  a17=arg[1]? arg[1][13] : 0;
  a19=arg[1]? arg[1][8] : 0;
  a20=(a19*a15);
  a11=(a11+a20);
  a21=arg[1]? arg[1][15] : 0;
  a22=arg[1]? arg[1][32] : 0;
  a07=(a07+a22);
  a07=(a07+a08);
  a07=(a07+a13);
  a13=cos(a07);
  a08=(a21*a13);
  a22=(a11+a08);
  a23=casadi_sq(a22);
  a19=(a19*a14);
  a06=(a06+a19);
  a07=sin(a07);
  a21=(a21*a07);
  a24=(a06+a21);
  a25=casadi_sq(a24);
  a23=(a23+a25);
  a23=(a17*a23);
  a00=(a00+a23);
  a23=arg[1]? arg[1][16] : 0;
  a25=arg[1]? arg[1][12] : 0;
  a13=(a25*a13);
  a11=(a11+a13);
  a26=casadi_sq(a11);
  a25=(a25*a07);
  a06=(a06+a25);
  a07=casadi_sq(a06);
  a26=(a26+a07);
  a26=(a23*a26);
  a00=(a00+a26);
  if (res[0]!=0) res[0][0]=a00;
  a01=(a01+a02);
  a02=(a12*a16);
  a02=(a02*a15);
  a00=(a12*a18);
  a00=(a00*a14);
  a02=(a02+a00);
  a02=(a05*a02);
  a02=(a01+a02);
  a08=(a20+a08);
  a00=(a08*a22);
  a21=(a19+a21);
  a26=(a21*a24);
  a00=(a00+a26);
  a00=(a17*a00);
  a02=(a02+a00);
  a20=(a20+a13);
  a13=(a20*a11);
  a19=(a19+a25);
  a25=(a19*a06);
  a13=(a13+a25);
  a13=(a23*a13);
  a02=(a02+a13);
  if (res[0]!=0) res[0][1]=a02;
  a18=(a05*a18);
  a24=(a17*a24);
  a18=(a18+a24);
  a06=(a23*a06);
  a18=(a18+a06);
  a04=(a04*a03);
  a09=(a04*a09);
  a09=(a18+a09);
  a09=(-a09);
  if (res[0]!=0) res[0][2]=a09;
  a16=(a05*a16);
  a22=(a17*a22);
  a16=(a16+a22);
  a11=(a23*a11);
  a16=(a16+a11);
  a04=(a04*a10);
  a04=(a16+a04);
  if (res[0]!=0) res[0][3]=a04;
  a18=(-a18);
  if (res[0]!=0) res[0][4]=a18;
  if (res[0]!=0) res[0][5]=a16;
  if (res[0]!=0) res[0][6]=a02;
  a02=casadi_sq(a12);
  a02=(a05*a02);
  a01=(a01+a02);
  a02=casadi_sq(a08);
  a10=casadi_sq(a21);
  a02=(a02+a10);
  a02=(a17*a02);
  a01=(a01+a02);
  a02=casadi_sq(a20);
  a10=casadi_sq(a19);
  a02=(a02+a10);
  a02=(a23*a02);
  a01=(a01+a02);
  if (res[0]!=0) res[0][7]=a01;
  a21=(a17*a21);
  a19=(a23*a19);
  a21=(a21+a19);
  a12=(a12*a05);
  a14=(a12*a14);
  a21=(a21+a14);
  a21=(-a21);
  if (res[0]!=0) res[0][8]=a21;
  a08=(a17*a08);
  a20=(a23*a20);
  a08=(a08+a20);
  a12=(a12*a15);
  a08=(a08+a12);
  if (res[0]!=0) res[0][9]=a08;
  if (res[0]!=0) res[0][10]=a21;
  if (res[0]!=0) res[0][11]=a08;
  if (res[0]!=0) res[0][12]=a09;
  if (res[0]!=0) res[0][13]=a21;
  a03=(a03+a05);
  a03=(a03+a17);
  a03=(a03+a23);
  if (res[0]!=0) res[0][14]=a03;
  a09=0.;
  if (res[0]!=0) res[0][15]=a09;
  a05=(a05+a17);
  a05=(a05+a23);
  if (res[0]!=0) res[0][16]=a05;
  if (res[0]!=0) res[0][17]=a09;
  if (res[0]!=0) res[0][18]=a04;
  if (res[0]!=0) res[0][19]=a08;
  if (res[0]!=0) res[0][20]=a09;
  if (res[0]!=0) res[0][21]=a03;
  if (res[0]!=0) res[0][22]=a09;
  if (res[0]!=0) res[0][23]=a05;
  if (res[0]!=0) res[0][24]=a18;
  if (res[0]!=0) res[0][25]=a21;
  if (res[0]!=0) res[0][26]=a05;
  if (res[0]!=0) res[0][27]=a09;
  if (res[0]!=0) res[0][28]=a05;
  if (res[0]!=0) res[0][29]=a09;
  if (res[0]!=0) res[0][30]=a16;
  if (res[0]!=0) res[0][31]=a08;
  if (res[0]!=0) res[0][32]=a09;
  if (res[0]!=0) res[0][33]=a05;
  if (res[0]!=0) res[0][34]=a09;
  if (res[0]!=0) res[0][35]=a05;
  return 0;
}

/* residual_jacobian_inputs:(i0[12],i1[6],i2[2],i3[39],i4[2])->(o0[6x2,2nz],o1[6x39,157nz],o2[6x2,7nz]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  casadi_real a144, a145, a146, a147, a148;
  a000=-1.;
  if (res[0]!=0) res[0][0]=a000;
  if (res[0]!=0) res[0][1]=a000;
  a000=arg[0]? arg[0][6] : 0;
  a001=casadi_sq(a000);
  a002=arg[3]? arg[3][19] : 0;
  a003=arg[0]? arg[0][0] : 0;
  a004=(a002+a003);
  a005=cos(a004);
  a006=arg[3]? arg[3][16] : 0;
  a007=arg[3]? arg[3][4] : 0;
  a008=sin(a004);
  a009=(a007*a008);
  a010=arg[3]? arg[3][8] : 0;
  a011=arg[0]? arg[0][1] : 0;
  a004=(a004+a011);
  a012=sin(a004);
  a013=(a010*a012);
  a014=(a009+a013);
  a015=arg[3]? arg[3][12] : 0;
  a016=arg[3]? arg[3][32] : 0;
  a002=(a002+a016);
  a002=(a002+a003);
  a002=(a002+a011);
  a011=sin(a002);
  a003=(a015*a011);
  a016=(a014+a003);
  a017=(a006*a016);
  a018=arg[3]? arg[3][13] : 0;
  a019=arg[3]? arg[3][15] : 0;
  a020=(a019*a011);
  a014=(a014+a020);
  a021=(a018*a014);
  a022=(a017+a021);
  a023=arg[3]? arg[3][9] : 0;
  a024=arg[3]? arg[3][11] : 0;
  a025=(a024*a012);
  a009=(a009+a025);
  a025=(a023*a009);
  a026=(a022+a025);
  a027=(a005*a026);
  a027=(a001*a027);
  a028=(a007*a005);
  a004=cos(a004);
  a029=(a010*a004);
  a030=(a028+a029);
  a002=cos(a002);
  a031=(a015*a002);
  a032=(a030+a031);
  a033=(a006*a032);
  a034=(a019*a002);
  a030=(a030+a034);
  a035=(a018*a030);
  a036=(a033+a035);
  a037=(a024*a004);
  a028=(a028+a037);
  a037=(a023*a028);
  a038=(a036+a037);
  a039=(a008*a038);
  a039=(a001*a039);
  a027=(a027-a039);
  a039=(a007*a001);
  a040=(a039*a005);
  a041=arg[0]? arg[0][7] : 0;
  a041=(a000+a041);
  a042=casadi_sq(a041);
  a043=(a010*a042);
  a044=(a043*a004);
  a044=(a040+a044);
  a045=(a015*a042);
  a046=(a045*a002);
  a046=(a044+a046);
  a047=(a006*a046);
  a048=arg[3]? arg[3][17] : 0;
  a049=(a048*a006);
  a047=(a047+a049);
  a049=arg[1]? arg[1][4] : 0;
  a050=arg[1]? arg[1][2] : 0;
  a051=(a049+a050);
  a052=(a006*a051);
  a047=(a047-a052);
  a003=(a013+a003);
  a052=arg[1]? arg[1][1] : 0;
  a053=(a006*a052);
  a054=(a003*a053);
  a054=(a047+a054);
  a055=(2.*a016);
  a056=arg[1]? arg[1][0] : 0;
  a057=(a006*a056);
  a055=(a055*a057);
  a054=(a054+a055);
  a055=(a019*a042);
  a058=(a055*a002);
  a044=(a044+a058);
  a058=(a018*a044);
  a059=(a048*a018);
  a058=(a058+a059);
  a059=(a018*a051);
  a058=(a058-a059);
  a013=(a013+a020);
  a020=(a018*a052);
  a059=(a013*a020);
  a059=(a058+a059);
  a060=(2.*a014);
  a061=(a018*a056);
  a060=(a060*a061);
  a059=(a059+a060);
  a060=(a054+a059);
  a062=(a024*a042);
  a063=(a062*a004);
  a040=(a040+a063);
  a063=(a023*a040);
  a064=(a048*a023);
  a063=(a063+a064);
  a064=(a023*a051);
  a063=(a063-a064);
  a064=(a023*a052);
  a065=(a012*a064);
  a066=(a024*a065);
  a063=(a063+a066);
  a066=(2.*a009);
  a067=(a023*a056);
  a066=(a066*a067);
  a063=(a063+a066);
  a060=(a060+a063);
  a066=(a008*a060);
  a027=(a027+a066);
  a066=arg[1]? arg[1][5] : 0;
  a068=arg[1]? arg[1][3] : 0;
  a069=(a066+a068);
  a070=(a006*a069);
  a071=(a039*a008);
  a072=(a043*a012);
  a072=(a071+a072);
  a073=(a045*a011);
  a073=(a072+a073);
  a074=(a006*a073);
  a075=arg[3]? arg[3][18] : 0;
  a076=(a075*a006);
  a074=(a074+a076);
  a070=(a070-a074);
  a031=(a029+a031);
  a074=(a031*a053);
  a074=(a070+a074);
  a076=(2.*a032);
  a076=(a076*a057);
  a074=(a074+a076);
  a076=(a018*a069);
  a077=(a055*a011);
  a072=(a072+a077);
  a077=(a018*a072);
  a078=(a075*a018);
  a077=(a077+a078);
  a076=(a076-a077);
  a029=(a029+a034);
  a034=(a029*a020);
  a034=(a076+a034);
  a077=(2.*a030);
  a077=(a077*a061);
  a034=(a034+a077);
  a077=(a074+a034);
  a078=(a023*a069);
  a079=(a062*a012);
  a071=(a071+a079);
  a079=(a023*a071);
  a080=(a075*a023);
  a079=(a079+a080);
  a078=(a078-a079);
  a079=(a004*a064);
  a080=(a024*a079);
  a078=(a078+a080);
  a080=(2.*a028);
  a080=(a080*a067);
  a078=(a078+a080);
  a077=(a077+a078);
  a080=(a005*a077);
  a027=(a027+a080);
  if (res[1]!=0) res[1][0]=a027;
  a027=(a006*a003);
  a080=(a018*a013);
  a081=(a027+a080);
  a082=(a024*a023);
  a083=(a082*a012);
  a084=(a081+a083);
  a085=(a005*a084);
  a085=(a001*a085);
  a086=(a006*a031);
  a087=(a018*a029);
  a088=(a086+a087);
  a089=(a082*a004);
  a090=(a088+a089);
  a091=(a008*a090);
  a091=(a001*a091);
  a085=(a085-a091);
  a091=(a003*a057);
  a092=(a013*a061);
  a093=(a091+a092);
  a094=(a012*a067);
  a095=(a024*a094);
  a093=(a093+a095);
  a096=(a008*a093);
  a085=(a085+a096);
  a096=(a031*a057);
  a097=(a029*a061);
  a098=(a096+a097);
  a099=(a004*a067);
  a100=(a024*a099);
  a098=(a098+a100);
  a101=(a005*a098);
  a085=(a085+a101);
  if (res[1]!=0) res[1][1]=a085;
  a085=(a006+a018);
  a101=(a085+a023);
  a102=(a005*a101);
  a102=(a001*a102);
  a103=(a057+a061);
  a103=(a103+a067);
  a104=(a008*a103);
  a102=(a102+a104);
  a102=(-a102);
  if (res[1]!=0) res[1][2]=a102;
  a104=(a005*a103);
  a105=(a008*a101);
  a105=(a001*a105);
  a104=(a104-a105);
  if (res[1]!=0) res[1][3]=a104;
  if (res[1]!=0) res[1][4]=a102;
  if (res[1]!=0) res[1][5]=a104;
  a104=arg[3]? arg[3][7] : 0;
  a102=(a104*a048);
  a105=(a102*a008);
  a106=(a104*a075);
  a107=(a106*a005);
  a105=(a105-a107);
  a107=(a005*a068);
  a108=(a104*a107);
  a105=(a105+a108);
  a108=(a008*a050);
  a109=(a104*a108);
  a105=(a105-a109);
  a109=casadi_sq(a104);
  a109=(a109*a056);
  a105=(a105+a109);
  if (res[1]!=0) res[1][6]=a105;
  a105=(a001*a005);
  a109=(a104*a105);
  a109=(a109+a048);
  a109=(a050-a109);
  a110=(a008*a056);
  a111=(a104*a110);
  a109=(a109-a111);
  if (res[1]!=0) res[1][7]=a109;
  a109=(a001*a008);
  a111=(a104*a109);
  a111=(a111+a075);
  a111=(a068-a111);
  a112=(a005*a056);
  a113=(a104*a112);
  a111=(a111+a113);
  if (res[1]!=0) res[1][8]=a111;
  if (res[1]!=0) res[1][9]=a056;
  a111=arg[3]? arg[3][5] : 0;
  a113=(a111*a008);
  a114=(a048*a113);
  a115=(a111*a005);
  a116=(a075*a115);
  a114=(a114-a116);
  a107=(a111*a107);
  a114=(a114+a107);
  a108=(a111*a108);
  a114=(a114-a108);
  a108=(2.*a104);
  a107=(a111*a056);
  a108=(a108*a107);
  a114=(a114+a108);
  if (res[1]!=0) res[1][10]=a114;
  a105=(a111*a105);
  a110=(a111*a110);
  a105=(a105+a110);
  a105=(-a105);
  if (res[1]!=0) res[1][11]=a105;
  a112=(a111*a112);
  a109=(a111*a109);
  a112=(a112-a109);
  if (res[1]!=0) res[1][12]=a112;
  a112=(a004*a022);
  a112=(a042*a112);
  a109=(a012*a036);
  a109=(a042*a109);
  a112=(a112-a109);
  a109=(a016*a053);
  a105=(a014*a020);
  a110=(a109+a105);
  a110=(a110+a054);
  a110=(a110+a059);
  a114=(a012*a110);
  a112=(a112+a114);
  a114=(a032*a053);
  a108=(a030*a020);
  a107=(a114+a108);
  a107=(a107+a074);
  a107=(a107+a034);
  a116=(a004*a107);
  a112=(a112+a116);
  if (res[1]!=0) res[1][13]=a112;
  a112=(a004*a081);
  a112=(a042*a112);
  a116=(a012*a088);
  a116=(a042*a116);
  a112=(a112-a116);
  a116=(2.*a003);
  a116=(a116*a053);
  a047=(a047+a116);
  a116=(a016*a057);
  a047=(a047+a116);
  a116=(2.*a013);
  a116=(a116*a020);
  a058=(a058+a116);
  a116=(a014*a061);
  a058=(a058+a116);
  a116=(a047+a058);
  a116=(a116+a091);
  a116=(a116+a092);
  a117=(a012*a116);
  a112=(a112+a117);
  a117=(2.*a031);
  a117=(a117*a053);
  a070=(a070+a117);
  a117=(a032*a057);
  a070=(a070+a117);
  a117=(2.*a029);
  a117=(a117*a020);
  a076=(a076+a117);
  a117=(a030*a061);
  a076=(a076+a117);
  a117=(a070+a076);
  a117=(a117+a096);
  a117=(a117+a097);
  a118=(a004*a117);
  a112=(a112+a118);
  if (res[1]!=0) res[1][14]=a112;
  a112=(a004*a085);
  a112=(a042*a112);
  a118=(a053+a020);
  a118=(a118+a057);
  a118=(a118+a061);
  a119=(a012*a118);
  a112=(a112+a119);
  a112=(-a112);
  if (res[1]!=0) res[1][15]=a112;
  a119=(a004*a118);
  a120=(a012*a085);
  a120=(a042*a120);
  a119=(a119-a120);
  if (res[1]!=0) res[1][16]=a119;
  if (res[1]!=0) res[1][17]=a112;
  if (res[1]!=0) res[1][18]=a119;
  a119=(a009*a040);
  a112=(a028*a071);
  a119=(a119-a112);
  a112=(a075*a028);
  a119=(a119-a112);
  a112=(a048*a009);
  a119=(a119+a112);
  a112=(a028*a069);
  a119=(a119+a112);
  a112=(a009*a051);
  a119=(a119-a112);
  a112=(a024*a028);
  a120=(a112*a004);
  a121=(a024*a009);
  a122=(a121*a012);
  a120=(a120+a122);
  a122=(a120*a052);
  a119=(a119+a122);
  a122=casadi_sq(a028);
  a123=casadi_sq(a009);
  a122=(a122+a123);
  a122=(a122*a056);
  a119=(a119+a122);
  if (res[1]!=0) res[1][19]=a119;
  a119=(a024*a048);
  a122=(a119*a012);
  a123=(a071*a004);
  a124=(a024*a123);
  a122=(a122-a124);
  a124=(a040*a012);
  a125=(a024*a124);
  a122=(a122+a125);
  a125=(a024*a075);
  a126=(a125*a004);
  a122=(a122-a126);
  a126=(a004*a069);
  a127=(a024*a126);
  a122=(a122+a127);
  a127=(a012*a051);
  a128=(a024*a127);
  a122=(a122-a128);
  a128=casadi_sq(a024);
  a128=(a128*a052);
  a122=(a122+a128);
  a120=(a120*a056);
  a122=(a122+a120);
  if (res[1]!=0) res[1][20]=a122;
  a122=(a040+a048);
  a120=(a049-a122);
  a120=(a120+a050);
  a128=(a012*a052);
  a129=(a024*a128);
  a120=(a120-a129);
  a130=(a009*a056);
  a120=(a120-a130);
  if (res[1]!=0) res[1][21]=a120;
  a120=(a071+a075);
  a131=(a066-a120);
  a131=(a131+a068);
  a132=(a004*a052);
  a133=(a024*a132);
  a131=(a131+a133);
  a134=(a028*a056);
  a131=(a131+a134);
  if (res[1]!=0) res[1][22]=a131;
  a122=(a051-a122);
  a122=(a122-a129);
  a122=(a122-a130);
  if (res[1]!=0) res[1][23]=a122;
  a120=(a069-a120);
  a120=(a120+a133);
  a120=(a120+a134);
  if (res[1]!=0) res[1][24]=a120;
  a120=(a052+a056);
  if (res[1]!=0) res[1][25]=a120;
  if (res[1]!=0) res[1][26]=a120;
  a134=(a004*a025);
  a134=(a042*a134);
  a133=(a012*a037);
  a133=(a042*a133);
  a134=(a134-a133);
  a065=(a009*a065);
  a134=(a134+a065);
  a079=(a028*a079);
  a134=(a134+a079);
  a079=(a012*a063);
  a134=(a134+a079);
  a079=(a004*a078);
  a134=(a134+a079);
  if (res[1]!=0) res[1][27]=a134;
  a134=(a023*a012);
  a079=(a048*a134);
  a123=(a023*a123);
  a079=(a079-a123);
  a124=(a023*a124);
  a079=(a079+a124);
  a124=(a023*a004);
  a123=(a075*a124);
  a079=(a079-a123);
  a126=(a023*a126);
  a079=(a079+a126);
  a127=(a023*a127);
  a079=(a079-a127);
  a127=(2.*a024);
  a127=(a127*a064);
  a079=(a079+a127);
  a127=(a004*a083);
  a127=(a042*a127);
  a079=(a079+a127);
  a127=(a012*a089);
  a127=(a042*a127);
  a079=(a079-a127);
  a009=(a009*a094);
  a079=(a079+a009);
  a028=(a028*a099);
  a079=(a079+a028);
  a028=(a012*a095);
  a079=(a079+a028);
  a028=(a004*a100);
  a079=(a079+a028);
  if (res[1]!=0) res[1][28]=a079;
  a128=(a023*a128);
  a079=(a004*a023);
  a079=(a042*a079);
  a128=(a128+a079);
  a128=(a128+a094);
  a128=(-a128);
  if (res[1]!=0) res[1][29]=a128;
  a132=(a023*a132);
  a094=(a012*a023);
  a094=(a042*a094);
  a132=(a132-a094);
  a132=(a132+a099);
  if (res[1]!=0) res[1][30]=a132;
  if (res[1]!=0) res[1][31]=a128;
  if (res[1]!=0) res[1][32]=a132;
  a132=(a002*a017);
  a132=(a042*a132);
  a128=(a011*a033);
  a128=(a042*a128);
  a132=(a132-a128);
  a109=(a109+a054);
  a054=(a011*a109);
  a132=(a132+a054);
  a114=(a114+a074);
  a074=(a002*a114);
  a132=(a132+a074);
  if (res[1]!=0) res[1][33]=a132;
  a132=(a002*a027);
  a132=(a042*a132);
  a074=(a011*a086);
  a074=(a042*a074);
  a132=(a132-a074);
  a047=(a047+a091);
  a091=(a011*a047);
  a132=(a132+a091);
  a070=(a070+a096);
  a096=(a002*a070);
  a132=(a132+a096);
  if (res[1]!=0) res[1][34]=a132;
  a132=(a002*a006);
  a132=(a042*a132);
  a053=(a053+a057);
  a057=(a011*a053);
  a132=(a132+a057);
  a132=(-a132);
  if (res[1]!=0) res[1][35]=a132;
  a057=(a002*a053);
  a096=(a011*a006);
  a096=(a042*a096);
  a057=(a057-a096);
  if (res[1]!=0) res[1][36]=a057;
  if (res[1]!=0) res[1][37]=a132;
  if (res[1]!=0) res[1][38]=a057;
  a057=(a014*a044);
  a132=(a030*a072);
  a057=(a057-a132);
  a132=(a075*a030);
  a057=(a057-a132);
  a132=(a048*a014);
  a057=(a057+a132);
  a132=(a030*a069);
  a057=(a057+a132);
  a132=(a014*a051);
  a057=(a057-a132);
  a132=(a029*a030);
  a096=(a013*a014);
  a132=(a132+a096);
  a096=(a132*a052);
  a057=(a057+a096);
  a096=casadi_sq(a030);
  a091=casadi_sq(a014);
  a096=(a096+a091);
  a096=(a096*a056);
  a057=(a057+a096);
  if (res[1]!=0) res[1][39]=a057;
  a057=(a013*a044);
  a096=(a029*a072);
  a057=(a057-a096);
  a096=(a075*a029);
  a057=(a057-a096);
  a096=(a048*a013);
  a057=(a057+a096);
  a096=(a029*a069);
  a057=(a057+a096);
  a096=(a013*a051);
  a057=(a057-a096);
  a096=casadi_sq(a029);
  a091=casadi_sq(a013);
  a096=(a096+a091);
  a096=(a096*a052);
  a057=(a057+a096);
  a132=(a132*a056);
  a057=(a057+a132);
  if (res[1]!=0) res[1][40]=a057;
  a044=(a044+a048);
  a057=(a049-a044);
  a057=(a057+a050);
  a013=(a013*a052);
  a057=(a057-a013);
  a014=(a014*a056);
  a057=(a057-a014);
  if (res[1]!=0) res[1][41]=a057;
  a072=(a072+a075);
  a057=(a066-a072);
  a057=(a057+a068);
  a029=(a029*a052);
  a057=(a057+a029);
  a030=(a030*a056);
  a057=(a057+a030);
  if (res[1]!=0) res[1][42]=a057;
  a044=(a051-a044);
  a044=(a044-a013);
  a044=(a044-a014);
  if (res[1]!=0) res[1][43]=a044;
  a072=(a069-a072);
  a072=(a072+a029);
  a072=(a072+a030);
  if (res[1]!=0) res[1][44]=a072;
  if (res[1]!=0) res[1][45]=a120;
  if (res[1]!=0) res[1][46]=a120;
  a120=(a002*a021);
  a120=(a042*a120);
  a072=(a011*a035);
  a072=(a042*a072);
  a120=(a120-a072);
  a105=(a105+a059);
  a059=(a011*a105);
  a120=(a120+a059);
  a108=(a108+a034);
  a034=(a002*a108);
  a120=(a120+a034);
  if (res[1]!=0) res[1][47]=a120;
  a120=(a002*a080);
  a120=(a042*a120);
  a034=(a011*a087);
  a034=(a042*a034);
  a120=(a120-a034);
  a058=(a058+a092);
  a092=(a011*a058);
  a120=(a120+a092);
  a076=(a076+a097);
  a097=(a002*a076);
  a120=(a120+a097);
  if (res[1]!=0) res[1][48]=a120;
  a120=(a002*a018);
  a120=(a042*a120);
  a020=(a020+a061);
  a061=(a011*a020);
  a120=(a120+a061);
  a120=(-a120);
  if (res[1]!=0) res[1][49]=a120;
  a061=(a002*a020);
  a097=(a011*a018);
  a042=(a042*a097);
  a061=(a061-a042);
  if (res[1]!=0) res[1][50]=a061;
  if (res[1]!=0) res[1][51]=a120;
  if (res[1]!=0) res[1][52]=a061;
  a061=(a016*a046);
  a120=(a032*a073);
  a061=(a061-a120);
  a120=(a075*a032);
  a061=(a061-a120);
  a120=(a048*a016);
  a061=(a061+a120);
  a120=(a032*a069);
  a061=(a061+a120);
  a120=(a016*a051);
  a061=(a061-a120);
  a120=(a031*a032);
  a042=(a003*a016);
  a120=(a120+a042);
  a042=(a120*a052);
  a061=(a061+a042);
  a042=casadi_sq(a032);
  a097=casadi_sq(a016);
  a042=(a042+a097);
  a042=(a042*a056);
  a061=(a061+a042);
  if (res[1]!=0) res[1][53]=a061;
  a061=(a003*a046);
  a042=(a031*a073);
  a061=(a061-a042);
  a042=(a075*a031);
  a061=(a061-a042);
  a042=(a048*a003);
  a061=(a061+a042);
  a042=(a031*a069);
  a061=(a061+a042);
  a042=(a003*a051);
  a061=(a061-a042);
  a042=casadi_sq(a031);
  a097=casadi_sq(a003);
  a042=(a042+a097);
  a042=(a042*a052);
  a061=(a061+a042);
  a120=(a120*a056);
  a061=(a061+a120);
  if (res[1]!=0) res[1][54]=a061;
  a046=(a046+a048);
  a049=(a049-a046);
  a049=(a049+a050);
  a003=(a003*a052);
  a049=(a049-a003);
  a016=(a016*a056);
  a049=(a049-a016);
  if (res[1]!=0) res[1][55]=a049;
  a073=(a073+a075);
  a066=(a066-a073);
  a066=(a066+a068);
  a031=(a031*a052);
  a066=(a066+a031);
  a032=(a032*a056);
  a066=(a066+a032);
  if (res[1]!=0) res[1][56]=a066;
  a046=(a051-a046);
  a046=(a046-a003);
  a046=(a046-a016);
  if (res[1]!=0) res[1][57]=a046;
  a073=(a069-a073);
  a073=(a073+a031);
  a073=(a073+a032);
  if (res[1]!=0) res[1][58]=a073;
  a113=(a104*a113);
  a113=(a113+a017);
  a113=(a113+a021);
  a113=(a113+a025);
  if (res[1]!=0) res[1][59]=a113;
  a134=(a024*a134);
  a134=(a134+a027);
  a134=(a134+a080);
  if (res[1]!=0) res[1][60]=a134;
  a134=(a101+a111);
  a134=(-a134);
  if (res[1]!=0) res[1][61]=a134;
  a113=(-a101);
  if (res[1]!=0) res[1][62]=a113;
  a115=(a104*a115);
  a115=(a115+a033);
  a115=(a115+a035);
  a115=(a115+a037);
  a115=(-a115);
  if (res[1]!=0) res[1][63]=a115;
  a124=(a024*a124);
  a124=(a124+a086);
  a124=(a124+a087);
  a124=(-a124);
  if (res[1]!=0) res[1][64]=a124;
  if (res[1]!=0) res[1][65]=a134;
  if (res[1]!=0) res[1][66]=a113;
  a109=(a015*a109);
  a033=(a045*a033);
  a035=(a055*a035);
  a033=(a033+a035);
  a109=(a109-a033);
  a105=(a019*a105);
  a109=(a109+a105);
  a109=(a002*a109);
  a017=(a045*a017);
  a021=(a055*a021);
  a017=(a017+a021);
  a114=(a015*a114);
  a017=(a017+a114);
  a108=(a019*a108);
  a017=(a017+a108);
  a017=(a011*a017);
  a109=(a109-a017);
  a017=(a121*a064);
  a036=(a043*a036);
  a037=(a062*a037);
  a036=(a036+a037);
  a017=(a017-a036);
  a110=(a010*a110);
  a017=(a017+a110);
  a063=(a024*a063);
  a017=(a017+a063);
  a017=(a004*a017);
  a022=(a043*a022);
  a025=(a062*a025);
  a022=(a022+a025);
  a064=(a112*a064);
  a022=(a022+a064);
  a107=(a010*a107);
  a022=(a022+a107);
  a078=(a024*a078);
  a022=(a022+a078);
  a022=(a012*a022);
  a017=(a017-a022);
  a017=(a109+a017);
  a102=(a102*a111);
  a038=(a039*a038);
  a102=(a102-a038);
  a104=(a104*a111);
  a050=(a104*a050);
  a102=(a102-a050);
  a060=(a007*a060);
  a102=(a102+a060);
  a102=(a005*a102);
  a026=(a039*a026);
  a106=(a106*a111);
  a026=(a026-a106);
  a068=(a104*a068);
  a026=(a026+a068);
  a077=(a007*a077);
  a026=(a026+a077);
  a026=(a008*a026);
  a102=(a102-a026);
  a017=(a017+a102);
  if (res[1]!=0) res[1][67]=a017;
  a047=(a015*a047);
  a086=(a045*a086);
  a087=(a055*a087);
  a086=(a086+a087);
  a047=(a047-a086);
  a058=(a019*a058);
  a047=(a047+a058);
  a047=(a002*a047);
  a027=(a045*a027);
  a080=(a055*a080);
  a027=(a027+a080);
  a070=(a015*a070);
  a027=(a027+a070);
  a076=(a019*a076);
  a027=(a027+a076);
  a027=(a011*a027);
  a047=(a047-a027);
  a119=(a119*a023);
  a040=(a082*a040);
  a119=(a119+a040);
  a051=(a082*a051);
  a119=(a119-a051);
  a088=(a043*a088);
  a119=(a119-a088);
  a089=(a062*a089);
  a119=(a119-a089);
  a121=(a121*a067);
  a119=(a119+a121);
  a116=(a010*a116);
  a119=(a119+a116);
  a095=(a024*a095);
  a119=(a119+a095);
  a119=(a004*a119);
  a069=(a082*a069);
  a071=(a082*a071);
  a125=(a125*a023);
  a071=(a071+a125);
  a069=(a069-a071);
  a081=(a043*a081);
  a069=(a069+a081);
  a083=(a062*a083);
  a069=(a069+a083);
  a112=(a112*a067);
  a069=(a069+a112);
  a117=(a010*a117);
  a069=(a069+a117);
  a100=(a024*a100);
  a069=(a069+a100);
  a069=(a012*a069);
  a119=(a119-a069);
  a119=(a047+a119);
  a093=(a007*a093);
  a090=(a039*a090);
  a093=(a093-a090);
  a093=(a005*a093);
  a084=(a039*a084);
  a098=(a007*a098);
  a084=(a084+a098);
  a084=(a008*a084);
  a093=(a093-a084);
  a119=(a119+a093);
  if (res[1]!=0) res[1][68]=a119;
  a045=(a045*a006);
  a055=(a055*a018);
  a045=(a045+a055);
  a055=(a011*a045);
  a015=(a015*a053);
  a019=(a019*a020);
  a015=(a015+a019);
  a019=(a002*a015);
  a055=(a055-a019);
  a043=(a043*a085);
  a062=(a062*a023);
  a043=(a043+a062);
  a062=(a012*a043);
  a082=(a082*a052);
  a010=(a010*a118);
  a082=(a082+a010);
  a024=(a024*a067);
  a082=(a082+a024);
  a024=(a004*a082);
  a062=(a062-a024);
  a062=(a055+a062);
  a001=(a104*a001);
  a039=(a039*a101);
  a001=(a001+a039);
  a101=(a008*a001);
  a104=(a104*a056);
  a007=(a007*a103);
  a104=(a104+a007);
  a103=(a005*a104);
  a101=(a101-a103);
  a101=(a062+a101);
  if (res[1]!=0) res[1][69]=a101;
  a002=(a002*a045);
  a011=(a011*a015);
  a002=(a002+a011);
  a004=(a004*a043);
  a012=(a012*a082);
  a004=(a004+a012);
  a004=(a002+a004);
  a001=(a005*a001);
  a104=(a008*a104);
  a001=(a001+a104);
  a001=(a004+a001);
  a001=(-a001);
  if (res[1]!=0) res[1][70]=a001;
  a001=(a008*a039);
  a104=(a005*a007);
  a001=(a001-a104);
  a062=(a062+a001);
  if (res[1]!=0) res[1][71]=a062;
  a005=(a005*a039);
  a008=(a008*a007);
  a005=(a005+a008);
  a004=(a004+a005);
  a004=(-a004);
  if (res[1]!=0) res[1][72]=a004;
  a004=0.;
  a005=arg[3]? arg[3][21] : 0;
  a008=-9.9999999999999995e-07;
  a007=(a008*a005);
  a039=9.9999999999999995e-07;
  a062=arg[3]? arg[3][20] : 0;
  a001=(a039*a062);
  a007=(a007+a001);
  a001=casadi_sq(a007);
  a104=arg[0]? arg[0][2] : 0;
  a012=casadi_sq(a104);
  a082=arg[0]? arg[0][3] : 0;
  a043=casadi_sq(a082);
  a012=(a012+a043);
  a043=casadi_fmax(a001,a012);
  a011=sqrt(a043);
  a015=(a005+a011);
  a015=(a015-a062);
  a045=(a004<a015);
  a101=1.3333333333333333e+00;
  a103=1.;
  a056=7.5000000000000000e-01;
  a024=-7.5000000000000000e-01;
  a067=arg[3]? arg[3][34] : 0;
  a010=casadi_sq(a067);
  a010=(a024*a010);
  a056=(a056+a010);
  a010=arg[4]? arg[4][0] : 0;
  a118=arg[3]? arg[3][35] : 0;
  a052=casadi_fmax(a010,a118);
  a023=(a056/a052);
  a085=-5.0000000000000000e-01;
  a019=pow(a043,a085);
  a020=(a019*a104);
  a053=arg[0]? arg[0][8] : 0;
  a018=(a020*a053);
  a006=(a019*a082);
  a119=arg[0]? arg[0][9] : 0;
  a093=(a006*a119);
  a018=(a018+a093);
  a093=(a023*a018);
  a093=(a103+a093);
  a084=1.0000000000000000e-300;
  a098=casadi_fmax(a084,a015);
  a090=arg[3]? arg[3][33] : 0;
  a069=pow(a098,a090);
  a100=(a062*a005);
  a117=(a062-a005);
  a100=(a100/a117);
  a112=sqrt(a100);
  a083=(a101*a112);
  a081=arg[3]? arg[3][23] : 0;
  a071=casadi_sq(a081);
  a071=(a103-a071);
  a125=arg[3]? arg[3][22] : 0;
  a071=(a071/a125);
  a095=arg[3]? arg[3][25] : 0;
  a116=casadi_sq(a095);
  a116=(a103-a116);
  a121=arg[3]? arg[3][24] : 0;
  a116=(a116/a121);
  a089=(a071+a116);
  a083=(a083/a089);
  a088=(a083*a093);
  a051=(a088*a069);
  a051=(a045?a051:0);
  a040=(a004<=a051);
  a027=(a051<=a004);
  a027=(a027+a040);
  a040=(a040/a027);
  a027=arg[3]? arg[3][36] : 0;
  a076=arg[3]? arg[3][37] : 0;
  a070=1.0000000000000000e-03;
  a080=arg[3]? arg[3][38] : 0;
  a058=(a070*a080);
  a086=casadi_fmax(a076,a058);
  a087=(a005*a000);
  a017=(a020*a119);
  a087=(a087+a017);
  a017=(a006*a053);
  a087=(a087-a017);
  a017=casadi_fabs(a087);
  a102=casadi_fmax(a086,a017);
  a026=(a027/a102);
  a077=(a026*a087);
  a068=(a017-a076);
  a080=(a080-a076);
  a068=(a068/a080);
  a106=casadi_fmax(a004,a068);
  a111=casadi_fmin(a103,a106);
  a060=(a111*a005);
  a050=(a077*a060);
  a050=(a040*a050);
  a038=(a069*a050);
  a022=(a093*a038);
  a078=(a022/a089);
  a078=(a101*a078);
  a112=(2.*a112);
  a078=(a078/a112);
  a107=(a078/a117);
  a064=(a005*a107);
  a100=(a100/a117);
  a078=(a100*a078);
  a064=(a064-a078);
  a025=(a084<=a015);
  a015=(a015<=a084);
  a015=(a015+a025);
  a025=(a025/a015);
  a015=(a090-a103);
  a063=pow(a098,a015);
  a063=(a090*a063);
  a050=(a088*a050);
  a110=(a063*a050);
  a110=(a025*a110);
  a064=(a064-a110);
  a064=(a045?a064:0);
  a007=(2.*a007);
  a036=(a012<=a001);
  a001=(a001<=a012);
  a001=(a036+a001);
  a036=(a036/a001);
  a011=(2.*a011);
  a001=(a110/a011);
  a001=(a045?a001:0);
  a012=-1.5000000000000000e+00;
  a043=pow(a043,a012);
  a043=(a085*a043);
  a038=(a083*a038);
  a037=(a023*a038);
  a108=(a119*a037);
  a108=(a082*a108);
  a037=(a053*a037);
  a037=(a104*a037);
  a108=(a108+a037);
  a108=(a045?a108:0);
  a051=casadi_fmax(a004,a051);
  a060=(a051*a060);
  a037=(a026*a060);
  a114=casadi_sign(a087);
  a021=(a004<=a068);
  a105=(a068<=a004);
  a105=(a105+a021);
  a021=(a021/a105);
  a105=(a106<=a103);
  a106=(a103<=a106);
  a106=(a106+a105);
  a105=(a105/a106);
  a106=(a077*a051);
  a033=(a106*a005);
  a033=(a105*a033);
  a033=(a021*a033);
  a035=(a033/a080);
  a113=(a086<=a017);
  a017=(a017<=a086);
  a134=(a017+a113);
  a113=(a113/a134);
  a026=(a026/a102);
  a060=(a087*a060);
  a026=(a026*a060);
  a124=(a113*a026);
  a124=(a035-a124);
  a124=(a114*a124);
  a037=(a037+a124);
  a124=(a053*a037);
  a124=(a082*a124);
  a108=(a108-a124);
  a124=(a119*a037);
  a124=(a104*a124);
  a108=(a108+a124);
  a108=(a043*a108);
  a001=(a001+a108);
  a001=(a036*a001);
  a001=(a007*a001);
  a108=(a039*a001);
  a064=(a064+a108);
  if (res[1]!=0) res[1][73]=a064;
  a064=(a027*a019);
  a064=(a064/a102);
  a108=(a064*a087);
  a124=(a111*a082);
  a115=(a108*a124);
  a020=(a020-a115);
  a020=(a040*a020);
  a115=(a069*a020);
  a073=(a093*a115);
  a032=(a073/a089);
  a032=(a101*a032);
  a032=(a032/a112);
  a031=(a032/a117);
  a046=(a005*a031);
  a032=(a100*a032);
  a046=(a046-a032);
  a020=(a088*a020);
  a016=(a063*a020);
  a016=(a025*a016);
  a046=(a046-a016);
  a046=(a045?a046:0);
  a003=(a016/a011);
  a003=(a045?a003:0);
  a066=(a051*a104);
  a124=(a051*a124);
  a075=(a087*a124);
  a049=(a075/a102);
  a048=(a027*a049);
  a066=(a066-a048);
  a115=(a083*a115);
  a048=(a023*a115);
  a061=(a119*a048);
  a061=(a082*a061);
  a061=(a045?a061:0);
  a066=(a066+a061);
  a048=(a053*a048);
  a048=(a104*a048);
  a048=(a045?a048:0);
  a066=(a066+a048);
  a048=(a064/a102);
  a075=(a048*a075);
  a061=(a113*a075);
  a120=(a108*a051);
  a042=(a120*a082);
  a042=(a105*a042);
  a042=(a021*a042);
  a097=(a042/a080);
  a061=(a061-a097);
  a061=(a114*a061);
  a124=(a064*a124);
  a061=(a061-a124);
  a124=(a053*a061);
  a124=(a082*a124);
  a066=(a066-a124);
  a124=(a119*a061);
  a124=(a104*a124);
  a066=(a066+a124);
  a066=(a043*a066);
  a003=(a003+a066);
  a003=(a036*a003);
  a003=(a007*a003);
  a066=(a039*a003);
  a046=(a046+a066);
  if (res[1]!=0) res[1][74]=a046;
  a046=(a111*a104);
  a066=(a108*a046);
  a066=(a066+a006);
  a066=(a040*a066);
  a006=(a069*a066);
  a093=(a093*a006);
  a124=(a093/a089);
  a124=(a101*a124);
  a124=(a124/a112);
  a117=(a124/a117);
  a112=(a005*a117);
  a100=(a100*a124);
  a112=(a112-a100);
  a088=(a088*a066);
  a063=(a063*a088);
  a025=(a025*a063);
  a112=(a112-a025);
  a112=(a045?a112:0);
  a011=(a025/a011);
  a011=(a045?a011:0);
  a046=(a051*a046);
  a087=(a087*a046);
  a063=(a087/a102);
  a066=(a027*a063);
  a051=(a051*a082);
  a066=(a066+a051);
  a006=(a083*a006);
  a051=(a023*a006);
  a124=(a119*a051);
  a124=(a082*a124);
  a124=(a045?a124:0);
  a066=(a066+a124);
  a051=(a053*a051);
  a051=(a104*a051);
  a051=(a045?a051:0);
  a066=(a066+a051);
  a064=(a064*a046);
  a120=(a120*a104);
  a105=(a105*a120);
  a021=(a021*a105);
  a105=(a021/a080);
  a048=(a048*a087);
  a113=(a113*a048);
  a113=(a105-a113);
  a114=(a114*a113);
  a064=(a064+a114);
  a053=(a053*a064);
  a053=(a082*a053);
  a066=(a066-a053);
  a119=(a119*a064);
  a119=(a104*a119);
  a066=(a066+a119);
  a043=(a043*a066);
  a011=(a011+a043);
  a036=(a036*a011);
  a007=(a007*a036);
  a036=(a039*a007);
  a112=(a112+a036);
  if (res[1]!=0) res[1][75]=a112;
  a106=(a106*a111);
  a078=(a045?a078:0);
  a106=(a106+a078);
  a107=(a062*a107);
  a107=(a045?a107:0);
  a106=(a106+a107);
  a110=(a045?a110:0);
  a106=(a106+a110);
  a001=(a008*a001);
  a106=(a106+a001);
  a037=(a000*a037);
  a106=(a106+a037);
  if (res[1]!=0) res[1][76]=a106;
  a031=(a062*a031);
  a032=(a032+a031);
  a032=(a032+a016);
  a032=(a045?a032:0);
  a003=(a008*a003);
  a032=(a032+a003);
  a061=(a000*a061);
  a032=(a032+a061);
  if (res[1]!=0) res[1][77]=a032;
  a062=(a062*a117);
  a100=(a100+a062);
  a100=(a100+a025);
  a100=(a045?a100:0);
  a007=(a008*a007);
  a100=(a100+a007);
  a064=(a000*a064);
  a100=(a100+a064);
  if (res[1]!=0) res[1][78]=a100;
  a071=(a071/a125);
  a089=(a083/a089);
  a022=(a089*a022);
  a100=(a071*a022);
  a100=(a045?a100:0);
  if (res[1]!=0) res[1][79]=a100;
  a073=(a089*a073);
  a100=(a071*a073);
  a100=(a045?a100:0);
  if (res[1]!=0) res[1][80]=a100;
  a089=(a089*a093);
  a071=(a071*a089);
  a071=(a045?a071:0);
  if (res[1]!=0) res[1][81]=a071;
  a081=(2.*a081);
  a071=(a022/a125);
  a071=(a081*a071);
  a071=(a045?a071:0);
  if (res[1]!=0) res[1][82]=a071;
  a071=(a073/a125);
  a071=(a081*a071);
  a071=(a045?a071:0);
  if (res[1]!=0) res[1][83]=a071;
  a125=(a089/a125);
  a081=(a081*a125);
  a081=(a045?a081:0);
  if (res[1]!=0) res[1][84]=a081;
  a116=(a116/a121);
  a081=(a116*a022);
  a081=(a045?a081:0);
  if (res[1]!=0) res[1][85]=a081;
  a081=(a116*a073);
  a081=(a045?a081:0);
  if (res[1]!=0) res[1][86]=a081;
  a116=(a116*a089);
  a116=(a045?a116:0);
  if (res[1]!=0) res[1][87]=a116;
  a095=(2.*a095);
  a022=(a022/a121);
  a022=(a095*a022);
  a022=(a045?a022:0);
  if (res[1]!=0) res[1][88]=a022;
  a073=(a073/a121);
  a073=(a095*a073);
  a073=(a045?a073:0);
  if (res[1]!=0) res[1][89]=a073;
  a089=(a089/a121);
  a095=(a095*a089);
  a095=(a045?a095:0);
  if (res[1]!=0) res[1][90]=a095;
  a095=arg[3]? arg[3][27] : 0;
  a089=(a008*a095);
  a121=arg[3]? arg[3][26] : 0;
  a073=(a039*a121);
  a089=(a089+a073);
  a073=casadi_sq(a089);
  a022=arg[0]? arg[0][4] : 0;
  a116=casadi_sq(a022);
  a081=arg[0]? arg[0][5] : 0;
  a125=casadi_sq(a081);
  a116=(a116+a125);
  a125=casadi_fmax(a073,a116);
  a071=sqrt(a125);
  a093=(a095+a071);
  a093=(a093-a121);
  a100=(a004<a093);
  a064=(a121*a095);
  a007=(a121-a095);
  a064=(a064/a007);
  a025=(a064/a007);
  a062=arg[4]? arg[4][1] : 0;
  a117=casadi_fmax(a062,a118);
  a056=(a056/a117);
  a032=pow(a125,a085);
  a061=(a032*a022);
  a003=arg[0]? arg[0][10] : 0;
  a016=(a061*a003);
  a031=(a032*a081);
  a106=arg[0]? arg[0][11] : 0;
  a037=(a031*a106);
  a016=(a016+a037);
  a037=(a056*a016);
  a037=(a103+a037);
  a001=casadi_fmax(a084,a093);
  a110=pow(a001,a090);
  a064=sqrt(a064);
  a107=(a101*a064);
  a078=arg[3]? arg[3][29] : 0;
  a112=casadi_sq(a078);
  a112=(a103-a112);
  a036=arg[3]? arg[3][28] : 0;
  a112=(a112/a036);
  a011=arg[3]? arg[3][31] : 0;
  a043=casadi_sq(a011);
  a043=(a103-a043);
  a066=arg[3]? arg[3][30] : 0;
  a043=(a043/a066);
  a119=(a112+a043);
  a107=(a107/a119);
  a053=(a107*a037);
  a114=(a053*a110);
  a114=(a100?a114:0);
  a113=(a004<=a114);
  a087=(a114<=a004);
  a087=(a087+a113);
  a113=(a113/a087);
  a087=(a121*a000);
  a120=(a095*a041);
  a046=(a087-a120);
  a051=(a031*a003);
  a046=(a046+a051);
  a124=(a061*a106);
  a046=(a046-a124);
  a092=casadi_fabs(a046);
  a034=casadi_fmax(a086,a092);
  a059=(a027/a034);
  a120=(a120-a087);
  a120=(a120+a124);
  a120=(a120-a051);
  a051=(a059*a120);
  a124=(a092-a076);
  a124=(a124/a080);
  a087=casadi_fmax(a004,a124);
  a072=casadi_fmin(a103,a087);
  a030=(a095-a121);
  a029=(a072*a030);
  a044=(a051*a029);
  a044=(a113*a044);
  a014=(a110*a044);
  a013=(a037*a014);
  a057=(a013/a119);
  a057=(a101*a057);
  a064=(2.*a064);
  a057=(a057/a064);
  a132=(a025*a057);
  a096=(-a132);
  a096=(a100?a096:0);
  a114=casadi_fmax(a004,a114);
  a091=(a051*a114);
  a074=(a091*a072);
  a096=(a096-a074);
  a057=(a057/a007);
  a054=(a095*a057);
  a054=(a100?a054:0);
  a096=(a096+a054);
  a054=(a084<=a093);
  a093=(a093<=a084);
  a093=(a093+a054);
  a054=(a054/a093);
  a015=pow(a001,a015);
  a090=(a090*a015);
  a044=(a053*a044);
  a015=(a090*a044);
  a015=(a054*a015);
  a093=(-a015);
  a093=(a100?a093:0);
  a096=(a096+a093);
  a029=(a114*a029);
  a093=(a059*a029);
  a084=(a000*a093);
  a096=(a096-a084);
  a089=(2.*a089);
  a084=(a116<=a073);
  a073=(a073<=a116);
  a073=(a084+a073);
  a084=(a084/a073);
  a071=(2.*a071);
  a073=(a015/a071);
  a073=(a100?a073:0);
  a125=pow(a125,a012);
  a085=(a085*a125);
  a014=(a107*a014);
  a125=(a056*a014);
  a012=(a106*a125);
  a012=(a081*a012);
  a125=(a003*a125);
  a125=(a022*a125);
  a012=(a012+a125);
  a012=(a100?a012:0);
  a125=(a003*a093);
  a125=(a081*a125);
  a012=(a012-a125);
  a125=(a106*a093);
  a125=(a022*a125);
  a012=(a012+a125);
  a046=casadi_sign(a046);
  a125=(a004<=a124);
  a004=(a124<=a004);
  a004=(a004+a125);
  a125=(a125/a004);
  a004=(a087<=a103);
  a103=(a103<=a087);
  a103=(a103+a004);
  a004=(a004/a103);
  a030=(a091*a030);
  a030=(a004*a030);
  a030=(a125*a030);
  a103=(a030/a080);
  a087=(a086<=a092);
  a092=(a092<=a086);
  a086=(a092+a087);
  a087=(a087/a086);
  a116=(a059/a034);
  a029=(a120*a029);
  a128=(a116*a029);
  a099=(a087*a128);
  a099=(a103-a099);
  a099=(a046*a099);
  a094=(a106*a099);
  a094=(a022*a094);
  a012=(a012-a094);
  a094=(a003*a099);
  a094=(a081*a094);
  a012=(a012+a094);
  a012=(a085*a012);
  a073=(a073+a012);
  a073=(a084*a073);
  a073=(a089*a073);
  a012=(a039*a073);
  a096=(a096+a012);
  a012=(a000*a099);
  a096=(a096+a012);
  if (res[1]!=0) res[1][91]=a096;
  a096=(a072*a095);
  a012=(a051*a096);
  a012=(a113*a012);
  a094=(a110*a012);
  a079=(a037*a094);
  a028=(a079/a119);
  a028=(a101*a028);
  a028=(a028/a064);
  a009=(a028/a007);
  a127=(a095*a009);
  a028=(a025*a028);
  a127=(a127-a028);
  a012=(a053*a012);
  a126=(a090*a012);
  a126=(a054*a126);
  a127=(a127-a126);
  a127=(a100?a127:0);
  a096=(a114*a096);
  a059=(a059*a096);
  a123=(a000*a059);
  a127=(a127-a123);
  a123=(a126/a071);
  a123=(a100?a123:0);
  a094=(a107*a094);
  a065=(a056*a094);
  a133=(a106*a065);
  a133=(a081*a133);
  a065=(a003*a065);
  a065=(a022*a065);
  a133=(a133+a065);
  a133=(a100?a133:0);
  a065=(a003*a059);
  a065=(a081*a065);
  a133=(a133-a065);
  a065=(a106*a059);
  a065=(a022*a065);
  a133=(a133+a065);
  a091=(a091*a095);
  a091=(a004*a091);
  a091=(a125*a091);
  a065=(a091/a080);
  a096=(a120*a096);
  a116=(a116*a096);
  a122=(a087*a116);
  a122=(a065-a122);
  a122=(a046*a122);
  a130=(a106*a122);
  a130=(a022*a130);
  a133=(a133-a130);
  a130=(a003*a122);
  a130=(a081*a130);
  a133=(a133+a130);
  a133=(a085*a133);
  a123=(a123+a133);
  a123=(a084*a123);
  a123=(a089*a123);
  a133=(a039*a123);
  a127=(a127+a133);
  a133=(a000*a122);
  a127=(a127+a133);
  if (res[1]!=0) res[1][92]=a127;
  a127=(a027*a032);
  a127=(a127/a034);
  a133=(a127*a120);
  a130=(a072*a081);
  a129=(a133*a130);
  a061=(a061-a129);
  a061=(a113*a061);
  a129=(a110*a061);
  a131=(a037*a129);
  a135=(a131/a119);
  a135=(a101*a135);
  a135=(a135/a064);
  a136=(a135/a007);
  a137=(a095*a136);
  a135=(a025*a135);
  a137=(a137-a135);
  a061=(a053*a061);
  a138=(a090*a061);
  a138=(a054*a138);
  a137=(a137-a138);
  a137=(a100?a137:0);
  a130=(a114*a130);
  a139=(a127*a130);
  a140=(a000*a139);
  a137=(a137+a140);
  a140=(a138/a071);
  a140=(a100?a140:0);
  a141=(a114*a022);
  a130=(a120*a130);
  a142=(a130/a034);
  a143=(a027*a142);
  a141=(a141-a143);
  a129=(a107*a129);
  a143=(a056*a129);
  a144=(a106*a143);
  a144=(a081*a144);
  a144=(a100?a144:0);
  a141=(a141+a144);
  a143=(a003*a143);
  a143=(a022*a143);
  a143=(a100?a143:0);
  a141=(a141+a143);
  a143=(a003*a139);
  a143=(a081*a143);
  a141=(a141+a143);
  a143=(a106*a139);
  a143=(a022*a143);
  a141=(a141-a143);
  a143=(a127/a034);
  a130=(a143*a130);
  a144=(a087*a130);
  a145=(a133*a114);
  a146=(a145*a081);
  a146=(a004*a146);
  a146=(a125*a146);
  a147=(a146/a080);
  a144=(a144-a147);
  a144=(a046*a144);
  a148=(a106*a144);
  a148=(a022*a148);
  a141=(a141-a148);
  a148=(a003*a144);
  a148=(a081*a148);
  a141=(a141+a148);
  a141=(a085*a141);
  a140=(a140+a141);
  a140=(a084*a140);
  a140=(a089*a140);
  a141=(a039*a140);
  a137=(a137+a141);
  a141=(a000*a144);
  a137=(a137+a141);
  if (res[1]!=0) res[1][93]=a137;
  a137=(a072*a022);
  a141=(a133*a137);
  a141=(a141+a031);
  a141=(a113*a141);
  a031=(a110*a141);
  a037=(a037*a031);
  a148=(a037/a119);
  a101=(a101*a148);
  a101=(a101/a064);
  a007=(a101/a007);
  a064=(a095*a007);
  a025=(a025*a101);
  a064=(a064-a025);
  a053=(a053*a141);
  a090=(a090*a053);
  a054=(a054*a090);
  a064=(a064-a054);
  a064=(a100?a064:0);
  a137=(a114*a137);
  a127=(a127*a137);
  a090=(a000*a127);
  a064=(a064-a090);
  a071=(a054/a071);
  a071=(a100?a071:0);
  a120=(a120*a137);
  a137=(a120/a034);
  a027=(a027*a137);
  a114=(a114*a081);
  a027=(a027+a114);
  a031=(a107*a031);
  a114=(a056*a031);
  a090=(a106*a114);
  a090=(a081*a090);
  a090=(a100?a090:0);
  a027=(a027+a090);
  a114=(a003*a114);
  a114=(a022*a114);
  a114=(a100?a114:0);
  a027=(a027+a114);
  a114=(a003*a127);
  a114=(a081*a114);
  a027=(a027-a114);
  a114=(a106*a127);
  a114=(a022*a114);
  a027=(a027+a114);
  a145=(a145*a022);
  a004=(a004*a145);
  a125=(a125*a004);
  a004=(a125/a080);
  a143=(a143*a120);
  a087=(a087*a143);
  a087=(a004-a087);
  a046=(a046*a087);
  a106=(a106*a046);
  a106=(a022*a106);
  a027=(a027-a106);
  a003=(a003*a046);
  a003=(a081*a003);
  a027=(a027+a003);
  a085=(a085*a027);
  a071=(a071+a085);
  a084=(a084*a071);
  a089=(a089*a084);
  a039=(a039*a089);
  a064=(a064+a039);
  a000=(a000*a046);
  a064=(a064+a000);
  if (res[1]!=0) res[1][94]=a064;
  a132=(a100?a132:0);
  a132=(a074+a132);
  a057=(a121*a057);
  a057=(a100?a057:0);
  a132=(a132+a057);
  a015=(a100?a015:0);
  a132=(a132+a015);
  a093=(a041*a093);
  a132=(a132+a093);
  a073=(a008*a073);
  a132=(a132+a073);
  a099=(a041*a099);
  a132=(a132-a099);
  if (res[1]!=0) res[1][95]=a132;
  a028=(a100?a028:0);
  a074=(a074+a028);
  a009=(a121*a009);
  a009=(a100?a009:0);
  a074=(a074+a009);
  a126=(a100?a126:0);
  a074=(a074+a126);
  a059=(a041*a059);
  a074=(a074+a059);
  a123=(a008*a123);
  a074=(a074+a123);
  a122=(a041*a122);
  a074=(a074-a122);
  if (res[1]!=0) res[1][96]=a074;
  a136=(a121*a136);
  a135=(a135+a136);
  a135=(a135+a138);
  a135=(a100?a135:0);
  a139=(a041*a139);
  a135=(a135-a139);
  a140=(a008*a140);
  a135=(a135+a140);
  a144=(a041*a144);
  a135=(a135-a144);
  if (res[1]!=0) res[1][97]=a135;
  a007=(a121*a007);
  a025=(a025+a007);
  a025=(a025+a054);
  a025=(a100?a025:0);
  a127=(a041*a127);
  a025=(a025+a127);
  a008=(a008*a089);
  a025=(a025+a008);
  a041=(a041*a046);
  a025=(a025-a041);
  if (res[1]!=0) res[1][98]=a025;
  a112=(a112/a036);
  a119=(a107/a119);
  a013=(a119*a013);
  a025=(a112*a013);
  a025=(a100?a025:0);
  if (res[1]!=0) res[1][99]=a025;
  a079=(a119*a079);
  a025=(a112*a079);
  a025=(a100?a025:0);
  if (res[1]!=0) res[1][100]=a025;
  a131=(a119*a131);
  a025=(a112*a131);
  a025=(a100?a025:0);
  if (res[1]!=0) res[1][101]=a025;
  a119=(a119*a037);
  a112=(a112*a119);
  a112=(a100?a112:0);
  if (res[1]!=0) res[1][102]=a112;
  a078=(2.*a078);
  a112=(a013/a036);
  a112=(a078*a112);
  a112=(a100?a112:0);
  if (res[1]!=0) res[1][103]=a112;
  a112=(a079/a036);
  a112=(a078*a112);
  a112=(a100?a112:0);
  if (res[1]!=0) res[1][104]=a112;
  a112=(a131/a036);
  a112=(a078*a112);
  a112=(a100?a112:0);
  if (res[1]!=0) res[1][105]=a112;
  a036=(a119/a036);
  a078=(a078*a036);
  a078=(a100?a078:0);
  if (res[1]!=0) res[1][106]=a078;
  a043=(a043/a066);
  a078=(a043*a013);
  a078=(a100?a078:0);
  if (res[1]!=0) res[1][107]=a078;
  a078=(a043*a079);
  a078=(a100?a078:0);
  if (res[1]!=0) res[1][108]=a078;
  a078=(a043*a131);
  a078=(a100?a078:0);
  if (res[1]!=0) res[1][109]=a078;
  a043=(a043*a119);
  a043=(a100?a043:0);
  if (res[1]!=0) res[1][110]=a043;
  a011=(2.*a011);
  a013=(a013/a066);
  a013=(a011*a013);
  a013=(a100?a013:0);
  if (res[1]!=0) res[1][111]=a013;
  a079=(a079/a066);
  a079=(a011*a079);
  a079=(a100?a079:0);
  if (res[1]!=0) res[1][112]=a079;
  a131=(a131/a066);
  a131=(a011*a131);
  a131=(a100?a131:0);
  if (res[1]!=0) res[1][113]=a131;
  a119=(a119/a066);
  a011=(a011*a119);
  a011=(a100?a011:0);
  if (res[1]!=0) res[1][114]=a011;
  if (res[1]!=0) res[1][115]=a109;
  if (res[1]!=0) res[1][116]=a047;
  if (res[1]!=0) res[1][117]=a055;
  a002=(-a002);
  if (res[1]!=0) res[1][118]=a002;
  if (res[1]!=0) res[1][119]=a055;
  if (res[1]!=0) res[1][120]=a002;
  a001=log(a001);
  a001=(a001*a110);
  a044=(a001*a044);
  a044=(a100?a044:0);
  a098=log(a098);
  a098=(a098*a069);
  a050=(a098*a050);
  a050=(a045?a050:0);
  a044=(a044+a050);
  if (res[1]!=0) res[1][121]=a044;
  a012=(a001*a012);
  a012=(a100?a012:0);
  if (res[1]!=0) res[1][122]=a012;
  a020=(a098*a020);
  a020=(a045?a020:0);
  if (res[1]!=0) res[1][123]=a020;
  a098=(a098*a088);
  a098=(a045?a098:0);
  if (res[1]!=0) res[1][124]=a098;
  a061=(a001*a061);
  a061=(a100?a061:0);
  if (res[1]!=0) res[1][125]=a061;
  a001=(a001*a053);
  a001=(a100?a001:0);
  if (res[1]!=0) res[1][126]=a001;
  a067=(2.*a067);
  a014=(a016*a014);
  a001=(a014/a117);
  a001=(a100?a001:0);
  a038=(a018*a038);
  a053=(a038/a052);
  a053=(a045?a053:0);
  a001=(a001+a053);
  a001=(a024*a001);
  a001=(a067*a001);
  if (res[1]!=0) res[1][127]=a001;
  a094=(a016*a094);
  a001=(a094/a117);
  a001=(a024*a001);
  a001=(a067*a001);
  a001=(a100?a001:0);
  if (res[1]!=0) res[1][128]=a001;
  a115=(a018*a115);
  a001=(a115/a052);
  a001=(a024*a001);
  a001=(a067*a001);
  a001=(a045?a001:0);
  if (res[1]!=0) res[1][129]=a001;
  a006=(a018*a006);
  a001=(a006/a052);
  a001=(a024*a001);
  a001=(a067*a001);
  a001=(a045?a001:0);
  if (res[1]!=0) res[1][130]=a001;
  a129=(a016*a129);
  a001=(a129/a117);
  a001=(a024*a001);
  a001=(a067*a001);
  a001=(a100?a001:0);
  if (res[1]!=0) res[1][131]=a001;
  a031=(a016*a031);
  a001=(a031/a117);
  a024=(a024*a001);
  a067=(a067*a024);
  a067=(a100?a067:0);
  if (res[1]!=0) res[1][132]=a067;
  a067=(a062<=a118);
  a062=(a118<=a062);
  a024=(a062+a067);
  a067=(a067/a024);
  a056=(a056/a117);
  a014=(a056*a014);
  a014=(a067*a014);
  a014=(-a014);
  a014=(a100?a014:0);
  a117=(a010<=a118);
  a118=(a118<=a010);
  a010=(a118+a117);
  a117=(a117/a010);
  a023=(a023/a052);
  a038=(a023*a038);
  a038=(a117*a038);
  a038=(-a038);
  a038=(a045?a038:0);
  a014=(a014+a038);
  if (res[1]!=0) res[1][133]=a014;
  a094=(a056*a094);
  a094=(a067*a094);
  a094=(-a094);
  a094=(a100?a094:0);
  if (res[1]!=0) res[1][134]=a094;
  a115=(a023*a115);
  a115=(a117*a115);
  a115=(-a115);
  a115=(a045?a115:0);
  if (res[1]!=0) res[1][135]=a115;
  a006=(a023*a006);
  a117=(a117*a006);
  a117=(-a117);
  a117=(a045?a117:0);
  if (res[1]!=0) res[1][136]=a117;
  a129=(a056*a129);
  a129=(a067*a129);
  a129=(-a129);
  a129=(a100?a129:0);
  if (res[1]!=0) res[1][137]=a129;
  a031=(a056*a031);
  a067=(a067*a031);
  a067=(-a067);
  a067=(a100?a067:0);
  if (res[1]!=0) res[1][138]=a067;
  a029=(a029/a034);
  a060=(a060/a102);
  a029=(a029+a060);
  if (res[1]!=0) res[1][139]=a029;
  a096=(a096/a034);
  if (res[1]!=0) res[1][140]=a096;
  a049=(a019*a049);
  a049=(-a049);
  if (res[1]!=0) res[1][141]=a049;
  a063=(a019*a063);
  if (res[1]!=0) res[1][142]=a063;
  a142=(a032*a142);
  a142=(-a142);
  if (res[1]!=0) res[1][143]=a142;
  a137=(a032*a137);
  if (res[1]!=0) res[1][144]=a137;
  a124=(a124/a080);
  a030=(a124*a030);
  a068=(a068/a080);
  a033=(a068*a033);
  a030=(a030+a033);
  a033=(a058<=a076);
  a076=(a076<=a058);
  a058=(a033+a076);
  a033=(a033/a058);
  a092=(a092/a086);
  a128=(a092*a128);
  a086=(a033*a128);
  a103=(a103+a086);
  a103=(a030-a103);
  a103=(a103-a035);
  a017=(a017/a134);
  a026=(a017*a026);
  a134=(a033*a026);
  a103=(a103-a134);
  if (res[1]!=0) res[1][145]=a103;
  a091=(a124*a091);
  a116=(a092*a116);
  a103=(a033*a116);
  a065=(a065+a103);
  a065=(a091-a065);
  if (res[1]!=0) res[1][146]=a065;
  a042=(a068*a042);
  a097=(a097-a042);
  a075=(a017*a075);
  a065=(a033*a075);
  a097=(a097+a065);
  if (res[1]!=0) res[1][147]=a097;
  a068=(a068*a021);
  a105=(a068-a105);
  a017=(a017*a048);
  a048=(a033*a017);
  a105=(a105-a048);
  if (res[1]!=0) res[1][148]=a105;
  a130=(a092*a130);
  a105=(a033*a130);
  a147=(a147+a105);
  a146=(a124*a146);
  a147=(a147-a146);
  if (res[1]!=0) res[1][149]=a147;
  a124=(a124*a125);
  a092=(a092*a143);
  a033=(a033*a092);
  a004=(a004+a033);
  a004=(a124-a004);
  if (res[1]!=0) res[1][150]=a004;
  a076=(a076/a058);
  a128=(a076*a128);
  a026=(a076*a026);
  a128=(a128+a026);
  a128=(a070*a128);
  a030=(a030+a128);
  a030=(-a030);
  if (res[1]!=0) res[1][151]=a030;
  a116=(a076*a116);
  a116=(a070*a116);
  a091=(a091+a116);
  a091=(-a091);
  if (res[1]!=0) res[1][152]=a091;
  a075=(a076*a075);
  a075=(a070*a075);
  a042=(a042+a075);
  if (res[1]!=0) res[1][153]=a042;
  a017=(a076*a017);
  a017=(a070*a017);
  a068=(a068+a017);
  a068=(-a068);
  if (res[1]!=0) res[1][154]=a068;
  a130=(a076*a130);
  a130=(a070*a130);
  a146=(a146+a130);
  if (res[1]!=0) res[1][155]=a146;
  a076=(a076*a092);
  a070=(a070*a076);
  a124=(a124+a070);
  a124=(-a124);
  if (res[1]!=0) res[1][156]=a124;
  a118=(a118/a010);
  a023=(a023*a118);
  a018=(a018*a023);
  a083=(a083*a018);
  a069=(a069*a083);
  a040=(a040*a069);
  a077=(a077*a040);
  a077=(a111*a077);
  a005=(a005*a077);
  a005=(-a005);
  a005=(a045?a005:0);
  if (res[2]!=0) res[2][0]=a005;
  a019=(a019*a040);
  a005=(a104*a019);
  a108=(a108*a040);
  a111=(a111*a108);
  a108=(a082*a111);
  a005=(a005-a108);
  a005=(-a005);
  a005=(a045?a005:0);
  if (res[2]!=0) res[2][1]=a005;
  a082=(a082*a019);
  a104=(a104*a111);
  a082=(a082+a104);
  a082=(-a082);
  a045=(a045?a082:0);
  if (res[2]!=0) res[2][2]=a045;
  a062=(a062/a024);
  a056=(a056*a062);
  a016=(a016*a056);
  a107=(a107*a016);
  a110=(a110*a107);
  a113=(a113*a110);
  a051=(a051*a113);
  a051=(a072*a051);
  a095=(a095*a051);
  a121=(a121*a051);
  a121=(a095-a121);
  a121=(-a121);
  a121=(a100?a121:0);
  if (res[2]!=0) res[2][3]=a121;
  a095=(-a095);
  a095=(a100?a095:0);
  if (res[2]!=0) res[2][4]=a095;
  a032=(a032*a113);
  a095=(a022*a032);
  a133=(a133*a113);
  a072=(a072*a133);
  a133=(a081*a072);
  a095=(a095-a133);
  a095=(-a095);
  a095=(a100?a095:0);
  if (res[2]!=0) res[2][5]=a095;
  a081=(a081*a032);
  a022=(a022*a072);
  a081=(a081+a022);
  a081=(-a081);
  a100=(a100?a081:0);
  if (res[2]!=0) res[2][6]=a100;
  return 0;
}

/* jac_forward_dynamics_inputs:(x[12],tau[2],p[39],v_imp[2])->(jac_xdot_tau[12x2,12nz],jac_xdot_p[12x39,234nz],jac_xdot_v_imp[12x2,12nz]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real **res1=res+3, *rr, *w01=w+149, *w02=w+161, *w04=w+163, *w05=w+165, *w07=w+171, *w08=w+207, *w09=w+209, *w10=w+366, *w11=w+373, *w13=w+385;
  casadi_real *w14=w+619;
  const casadi_real **arg1=arg+4, *cs, *ss, *wr01, *wr03, *wr06;
  wr01 = arg[0] ? arg[0] : casadi_zeros;
  casadi_copy(arg[1], 2, w02);
  wr03 = arg[2] ? arg[2] : casadi_zeros;
  casadi_copy(arg[3], 2, w04);
  arg1[0]=wr01;
  arg1[1]=w02;
  arg1[2]=wr03;
  arg1[3]=w04;
  res1[0]=w05;
  if (casadi_f1(arg1, res1, iw, w, 0)) return 1;
  wr06 = wr01+0;
  arg1[0]=wr06;
  arg1[1]=wr03;
  res1[0]=w07;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr = w05;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s0, ss, casadi_s1, lt, d, casadi_s2, w);
    casadi_ldl_solve(rr, 1, casadi_s1, lt, d, casadi_s2, w);
  }
  arg1[0]=wr01;
  arg1[1]=w05;
  arg1[2]=w02;
  arg1[3]=wr03;
  arg1[4]=w04;
  res1[0]=w08;
  res1[1]=w09;
  res1[2]=w10;
  if (casadi_f3(arg1, res1, iw, w, 0)) return 1;
  casadi_densify(w08, casadi_s3, w01, 0);
  rr = w01;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s0, ss, casadi_s1, lt, d, casadi_s2, w);
    casadi_ldl_solve(rr, 2, casadi_s1, lt, d, casadi_s2, w);
  }
  for (i=0, rr=w01, cs=w01; i<12; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w11, cs=w01; i<2; ++i) for (j=0; j<6; ++j) rr[i+j*2] = *cs++;
  rr=w01;
  for (i=0, cs=w11; i<12; ++i) *rr++ = *cs++;
  casadi_trans(w01,casadi_s5, w11, casadi_s4, iw);
  casadi_copy(w11, 12, res[0]);
  casadi_densify(w09, casadi_s6, w13, 0);
  rr = w13;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s0, ss, casadi_s1, lt, d, casadi_s2, w);
    casadi_ldl_solve(rr, 39, casadi_s1, lt, d, casadi_s2, w);
  }
  for (i=0, rr=w13, cs=w13; i<234; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w14, cs=w13; i<39; ++i) for (j=0; j<6; ++j) rr[i+j*39] = *cs++;
  rr=w13;
  for (i=0, cs=w14; i<234; ++i) *rr++ = *cs++;
  casadi_trans(w13,casadi_s8, w14, casadi_s7, iw);
  casadi_copy(w14, 234, res[1]);
  casadi_densify(w10, casadi_s9, w11, 0);
  rr = w11;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s0, ss, casadi_s1, lt, d, casadi_s2, w);
    casadi_ldl_solve(rr, 2, casadi_s1, lt, d, casadi_s2, w);
  }
  for (i=0, rr=w11, cs=w11; i<12; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w01, cs=w11; i<2; ++i) for (j=0; j<6; ++j) rr[i+j*2] = *cs++;
  rr=w11;
  for (i=0, cs=w01; i<12; ++i) *rr++ = *cs++;
  casadi_trans(w11,casadi_s5, w01, casadi_s4, iw);
  casadi_copy(w01, 12, res[2]);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_inputs(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_inputs_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_inputs_release(int mem) {
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_inputs_incref(void) {
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_inputs_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int jac_forward_dynamics_inputs_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int jac_forward_dynamics_inputs_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real jac_forward_dynamics_inputs_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jac_forward_dynamics_inputs_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau";
    case 2: return "p";
    case 3: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jac_forward_dynamics_inputs_name_out(casadi_int i) {
  switch (i) {
    case 0: return "jac_xdot_tau";
    case 1: return "jac_xdot_p";
    case 2: return "jac_xdot_v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_forward_dynamics_inputs_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s10;
    case 1: return casadi_s11;
    case 2: return casadi_s12;
    case 3: return casadi_s11;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_forward_dynamics_inputs_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s7;
    case 2: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_inputs_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9;
  if (sz_res) *sz_res = 6;
  if (sz_iw) *sz_iw = 40;
  if (sz_w) *sz_w = 853;
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_inputs_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 6*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 40*sizeof(casadi_int);
  if (sz_w) *sz_w = 853*sizeof(casadi_real);
  return 0;
}


/* Wrappers over the eager library, which this one is linked against. */
int jac_state(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int jac_state_work(casadi_int* sz_arg, casadi_int* sz_res, casadi_int* sz_iw, casadi_int* sz_w);
const casadi_int* jac_state_sparsity_in(casadi_int i);
const casadi_int* jac_state_sparsity_out(casadi_int i);
int forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int forward_dynamics_work(casadi_int* sz_arg, casadi_int* sz_res, casadi_int* sz_iw, casadi_int* sz_w);
const casadi_int* forward_dynamics_sparsity_in(casadi_int i);
const casadi_int* forward_dynamics_sparsity_out(casadi_int i);

static const casadi_int jp_nominal_sparsity[4] = {12, 1, 0, 0};

static casadi_int jp_max(casadi_int a, casadi_int b) { return a > b ? a : b; }

/* The state block from jac_state, the others from jac_forward_dynamics_inputs. A callee uses
 * the pointer arrays beyond its own inputs and outputs as scratch, and the caller's
 * arrays are its own (kept between calls), so this function's fifth input and its
 * outputs are put back before it returns; a block not asked for (a null pointer) is
 * not computed. */
static int jp_full_jacobian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w) {
  const casadi_real* nominal = arg[4];
  casadi_real* out[4];
  casadi_int i;
  int status = 0;
  for (i = 0; i < 4; ++i) out[i] = res[i];
  if (out[0]) {
    res[0] = out[0];
    status = jac_state(arg, res, iw, w, 0);
  }
  if (!status && (out[1] || out[2] || out[3])) {
    res[0] = out[1];
    res[1] = out[2];
    res[2] = out[3];
    status = jac_forward_dynamics_inputs(arg, res, iw, w, 0);
  }
  arg[4] = nominal;
  for (i = 0; i < 4; ++i) res[i] = out[i];
  return status;
}

static void jp_full_jacobian_work(casadi_int* sz_arg, casadi_int* sz_res, casadi_int* sz_iw, casadi_int* sz_w) {
  casadi_int a0, r0, i0, w0, a1, r1, i1, w1;
  jac_state_work(&a0, &r0, &i0, &w0);
  jac_forward_dynamics_inputs_work(&a1, &r1, &i1, &w1);
  if (sz_arg) *sz_arg = jp_max(jp_max(a0, a1), 5);
  if (sz_res) *sz_res = jp_max(jp_max(r0, r1), 4);
  if (sz_iw) *sz_iw = jp_max(i0, i1);
  if (sz_w) *sz_w = jp_max(w0, w1);
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void) mem;
  return jp_full_jacobian(arg, res, iw, w);
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_release(int mem) {
  (void) mem;
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_incref(void) {
}

CASADI_SYMBOL_EXPORT void jac_forward_dynamics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int jac_forward_dynamics_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int jac_forward_dynamics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real jac_forward_dynamics_default_in(casadi_int i) {
  (void) i;
  return 0;
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
  if (i >= 0 && i < 4) return jac_forward_dynamics_inputs_sparsity_in(i);
  return i == 4 ? jp_nominal_sparsity : 0;
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_forward_dynamics_sparsity_out(casadi_int i) {
  if (i == 0) return jac_state_sparsity_out(0);
  if (i > 0 && i < 4) return jac_forward_dynamics_inputs_sparsity_out(i - 1);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  jp_full_jacobian_work(sz_arg, sz_res, sz_iw, sz_w);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  jp_full_jacobian_work(sz_arg, sz_res, sz_iw, sz_w);
  if (sz_arg) *sz_arg *= sizeof(const casadi_real*);
  if (sz_res) *sz_res *= sizeof(casadi_real*);
  if (sz_iw) *sz_iw *= sizeof(casadi_int);
  if (sz_w) *sz_w *= sizeof(casadi_real);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_differentiable_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void) mem;
  return jp_full_jacobian(arg, res, iw, w);
}

CASADI_SYMBOL_EXPORT int jac_differentiable_forward_dynamics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void jac_differentiable_forward_dynamics_release(int mem) {
  (void) mem;
}

CASADI_SYMBOL_EXPORT void jac_differentiable_forward_dynamics_incref(void) {
}

CASADI_SYMBOL_EXPORT void jac_differentiable_forward_dynamics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int jac_differentiable_forward_dynamics_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int jac_differentiable_forward_dynamics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real jac_differentiable_forward_dynamics_default_in(casadi_int i) {
  (void) i;
  return 0;
}

CASADI_SYMBOL_EXPORT const char* jac_differentiable_forward_dynamics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau";
    case 2: return "p";
    case 3: return "v_imp";
    case 4: return "out_xdot";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jac_differentiable_forward_dynamics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "jac_xdot_x";
    case 1: return "jac_xdot_tau";
    case 2: return "jac_xdot_p";
    case 3: return "jac_xdot_v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_differentiable_forward_dynamics_sparsity_in(casadi_int i) {
  if (i >= 0 && i < 4) return jac_forward_dynamics_inputs_sparsity_in(i);
  return i == 4 ? jp_nominal_sparsity : 0;
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_differentiable_forward_dynamics_sparsity_out(casadi_int i) {
  if (i == 0) return jac_state_sparsity_out(0);
  if (i > 0 && i < 4) return jac_forward_dynamics_inputs_sparsity_out(i - 1);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_differentiable_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  jp_full_jacobian_work(sz_arg, sz_res, sz_iw, sz_w);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_differentiable_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  jp_full_jacobian_work(sz_arg, sz_res, sz_iw, sz_w);
  if (sz_arg) *sz_arg *= sizeof(const casadi_real*);
  if (sz_res) *sz_res *= sizeof(casadi_real*);
  if (sz_iw) *sz_iw *= sizeof(casadi_int);
  if (sz_w) *sz_w *= sizeof(casadi_real);
  return 0;
}

CASADI_SYMBOL_EXPORT int differentiable_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void) mem;
  return forward_dynamics(arg, res, iw, w, 0);
}

CASADI_SYMBOL_EXPORT int differentiable_forward_dynamics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void differentiable_forward_dynamics_release(int mem) {
  (void) mem;
}

CASADI_SYMBOL_EXPORT void differentiable_forward_dynamics_incref(void) {
}

CASADI_SYMBOL_EXPORT void differentiable_forward_dynamics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int differentiable_forward_dynamics_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int differentiable_forward_dynamics_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real differentiable_forward_dynamics_default_in(casadi_int i) {
  (void) i;
  return 0;
}

CASADI_SYMBOL_EXPORT const char* differentiable_forward_dynamics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau";
    case 2: return "p";
    case 3: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* differentiable_forward_dynamics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "xdot";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* differentiable_forward_dynamics_sparsity_in(casadi_int i) {
  return forward_dynamics_sparsity_in(i);
}

CASADI_SYMBOL_EXPORT const casadi_int* differentiable_forward_dynamics_sparsity_out(casadi_int i) {
  return forward_dynamics_sparsity_out(i);
}

CASADI_SYMBOL_EXPORT int differentiable_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  forward_dynamics_work(sz_arg, sz_res, sz_iw, sz_w);
  return 0;
}

CASADI_SYMBOL_EXPORT int differentiable_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  forward_dynamics_work(sz_arg, sz_res, sz_iw, sz_w);
  if (sz_arg) *sz_arg *= sizeof(const casadi_real*);
  if (sz_res) *sz_res *= sizeof(casadi_real*);
  if (sz_iw) *sz_iw *= sizeof(casadi_int);
  if (sz_w) *sz_w *= sizeof(casadi_real);
  return 0;
}

