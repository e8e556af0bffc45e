/* GENERATED FILE: DO NOT EDIT.
 * Regenerate: `jointplay derive robot.toml --out <this folder>`, or for the models
 * checked in under generated/: `pytest tests/test_generated.py --update-generated`.
 * model: paper_4dof
 * generator: jointplay.derive 0.1.0+264b877a7099, casadi 3.8.2, sympy 1.14.0
 * input hash: a7fcedf7abba3d05c149bc7f61d0ca2818ec66c6c211e0fe00f465c45ffe95cc
 * Every input and output slot is described, with names and units, in layout.json.
 * Functions (inputs -> outputs; column vectors, dense, float64):
 *   mass_matrix(q[6], p[39]) -> M[6x6]
 *   forcing(x[12], tau[2], p[39], v_imp[2]) -> f[6x1]
 *   forward_dynamics(x[12], tau[2], p[39], v_imp[2]) -> xdot[12x1]
 *   jac_forward_dynamics: d forward_dynamics / d each input, CasADi's calling convention
 *   contact(x[12], p[39], v_imp[2]) -> delta[2x1], delta_dot[2x1], v_t[2x1], f_n[2x1], f_t[2x1], f_x[2x1], f_y[2x1], dissipation[2x1]
 *   energy(x[12], p[39]) -> kinetic[1x1], gravity[1x1], contact[1x1], total[1x1]
 *   end_effector(x[12], udot[6], p[39]) -> position[2x1], velocity[2x1], acceleration[2x1]
 *   rk4_step(x[12], tau_stages[2], h[1], p[39], v_imp[2]) -> x_next[12x1]
 *   radau_step(x[12], tau_stages[2], h[1], p[39], v_imp[2]) -> x_next[12x1], newton_increment[1x1]
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
#define casadi_c0 CASADI_PREFIX(c0)
#define casadi_c1 CASADI_PREFIX(c1)
#define casadi_c2 CASADI_PREFIX(c2)
#define casadi_clear CASADI_PREFIX(clear)
#define casadi_copy CASADI_PREFIX(copy)
#define casadi_densify CASADI_PREFIX(densify)
#define casadi_dot CASADI_PREFIX(dot)
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_f1 CASADI_PREFIX(f1)
#define casadi_f2 CASADI_PREFIX(f2)
#define casadi_f3 CASADI_PREFIX(f3)
#define casadi_f4 CASADI_PREFIX(f4)
#define casadi_f5 CASADI_PREFIX(f5)
#define casadi_f6 CASADI_PREFIX(f6)
#define casadi_f7 CASADI_PREFIX(f7)
#define casadi_f8 CASADI_PREFIX(f8)
#define casadi_f9 CASADI_PREFIX(f9)
#define casadi_fabs CASADI_PREFIX(fabs)
#define casadi_fill CASADI_PREFIX(fill)
#define casadi_fmax CASADI_PREFIX(fmax)
#define casadi_fmin CASADI_PREFIX(fmin)
#define casadi_house CASADI_PREFIX(house)
#define casadi_if_else CASADI_PREFIX(if_else)
#define casadi_kron_dense_sparse CASADI_PREFIX(kron_dense_sparse)
#define casadi_ldl CASADI_PREFIX(ldl)
#define casadi_ldl_solve CASADI_PREFIX(ldl_solve)
#define casadi_ldl_trs CASADI_PREFIX(ldl_trs)
#define casadi_mtimes_dense CASADI_PREFIX(mtimes_dense)
#define casadi_norm_inf CASADI_PREFIX(norm_inf)
#define casadi_project CASADI_PREFIX(project)
#define casadi_qr CASADI_PREFIX(qr)
#define casadi_qr_colcomb CASADI_PREFIX(qr_colcomb)
#define casadi_qr_mv CASADI_PREFIX(qr_mv)
#define casadi_qr_singular CASADI_PREFIX(qr_singular)
#define casadi_qr_solve CASADI_PREFIX(qr_solve)
#define casadi_qr_trs CASADI_PREFIX(qr_trs)
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
#define casadi_s20 CASADI_PREFIX(s20)
#define casadi_s21 CASADI_PREFIX(s21)
#define casadi_s22 CASADI_PREFIX(s22)
#define casadi_s23 CASADI_PREFIX(s23)
#define casadi_s24 CASADI_PREFIX(s24)
#define casadi_s25 CASADI_PREFIX(s25)
#define casadi_s26 CASADI_PREFIX(s26)
#define casadi_s27 CASADI_PREFIX(s27)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_s8 CASADI_PREFIX(s8)
#define casadi_s9 CASADI_PREFIX(s9)
#define casadi_scal CASADI_PREFIX(scal)
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

void casadi_project(const casadi_real* x, const casadi_int* sp_x, casadi_real* y, const casadi_int* sp_y, casadi_real* w) {
  casadi_int ncol_x, ncol_y, i, el;
  const casadi_int *colind_x, *row_x, *colind_y, *row_y;
  ncol_x = sp_x[1];
  colind_x = sp_x+2; row_x = sp_x + 2 + ncol_x+1;
  ncol_y = sp_y[1];
  colind_y = sp_y+2; row_y = sp_y + 2 + ncol_y+1;
  for (i=0; i<ncol_x; ++i) {
    for (el=colind_y[i]; el<colind_y[i+1]; ++el) w[row_y[el]] = 0;
    for (el=colind_x[i]; el<colind_x[i+1]; ++el) w[row_x[el]] = x[el];
    for (el=colind_y[i]; el<colind_y[i+1]; ++el) y[el] = w[row_y[el]];
  }
}

void casadi_kron_dense_sparse(const casadi_real* a, casadi_int mA, casadi_int nA,
                              const casadi_real* b, const casadi_int* sp_b,
                              casadi_real* r) {
    casadi_int nB = sp_b[1];
    const casadi_int* b_colind = sp_b+2;
    casadi_int j, s, i, b_el, k;
    casadi_real a_val;
    k = 0;
    for (j=0; j<nA; ++j) {
      for (s=0; s<nB; ++s) {
        for (i=0; i<mA; ++i) {
          a_val = a[j*mA + i];
          for (b_el=b_colind[s]; b_el<b_colind[s+1]; ++b_el) {
            r[k++] = a_val * b[b_el];
          }
        }
      }
    }
}

casadi_real casadi_if_else(casadi_real c, casadi_real x, casadi_real y) { return c!=0 ? x : y;}

void casadi_scal(casadi_int n, casadi_real alpha, casadi_real* x) {
  casadi_int i;
  if (!x) return;
  for (i=0; i<n; ++i) *x++ *= alpha;
}

casadi_real casadi_dot(casadi_int n, const casadi_real* x, const casadi_real* y) {
  casadi_int i;
  casadi_real r = 0;
  for (i=0; i<n; ++i) r += *x++ * *y++;
  return r;
}

casadi_real casadi_house(casadi_real* v, casadi_real* beta, casadi_int nv) {
  casadi_int i;
  casadi_real v0, sigma, s, sigma_is_zero, v0_nonpos;
  v0 = v[0];
  sigma=0;
  for (i=1; i<nv; ++i) sigma += v[i]*v[i];
  s = sqrt(v0*v0 + sigma);
  sigma_is_zero = sigma==0;
  v0_nonpos = v0<=0;
  v[0] = casadi_if_else(sigma_is_zero, 1,
                 casadi_if_else(v0_nonpos, v0-s, -sigma/(v0+s)));
  *beta = casadi_if_else(sigma_is_zero, 2*v0_nonpos, -1/(s*v[0]));
  return s;
}
void casadi_qr(const casadi_int* sp_a, const casadi_real* nz_a, casadi_real* x,
               const casadi_int* sp_v, casadi_real* nz_v, const casadi_int* sp_r, casadi_real* nz_r, casadi_real* beta,
               const casadi_int* prinv, const casadi_int* pc) {
   casadi_int ncol, nrow, r, c, k, k1;
   casadi_real alpha;
   const casadi_int *a_colind, *a_row, *v_colind, *v_row, *r_colind, *r_row;
   ncol = sp_a[1];
   a_colind=sp_a+2; a_row=sp_a+2+ncol+1;
   nrow = sp_v[0];
   v_colind=sp_v+2; v_row=sp_v+2+ncol+1;
   r_colind=sp_r+2; r_row=sp_r+2+ncol+1;
   for (r=0; r<nrow; ++r) x[r] = 0;
   for (c=0; c<ncol; ++c) {
     for (k=a_colind[pc[c]]; k<a_colind[pc[c]+1]; ++k) x[prinv[a_row[k]]] = nz_a[k];
     for (k=r_colind[c]; k<r_colind[c+1] && (r=r_row[k])<c; ++k) {
       alpha = 0;
       for (k1=v_colind[r]; k1<v_colind[r+1]; ++k1) alpha += nz_v[k1]*x[v_row[k1]];
       alpha *= beta[r];
       for (k1=v_colind[r]; k1<v_colind[r+1]; ++k1) x[v_row[k1]] -= alpha*nz_v[k1];
       *nz_r++ = x[r];
       x[r] = 0;
     }
     for (k=v_colind[c]; k<v_colind[c+1]; ++k) {
       nz_v[k] = x[v_row[k]];
       x[v_row[k]] = 0;
     }
     *nz_r++ = casadi_house(nz_v + v_colind[c], beta + c, v_colind[c+1] - v_colind[c]);
   }
 }
void casadi_qr_mv(const casadi_int* sp_v, const casadi_real* v, const casadi_real* beta, casadi_real* x,
                  casadi_int tr) {
  casadi_int ncol, c, c1, k;
  casadi_real alpha;
  const casadi_int *colind, *row;
  ncol=sp_v[1];
  colind=sp_v+2; row=sp_v+2+ncol+1;
  for (c1=0; c1<ncol; ++c1) {
    c = tr ? c1 : ncol-1-c1;
    alpha=0;
    for (k=colind[c]; k<colind[c+1]; ++k) alpha += v[k]*x[row[k]];
    alpha *= beta[c];
    for (k=colind[c]; k<colind[c+1]; ++k) x[row[k]] -= alpha*v[k];
  }
}
void casadi_qr_trs(const casadi_int* sp_r, const casadi_real* nz_r, casadi_real* x, casadi_int tr) {
  casadi_int ncol, r, c, k;
  const casadi_int *colind, *row;
  ncol=sp_r[1];
  colind=sp_r+2; row=sp_r+2+ncol+1;
  if (tr) {
    for (c=0; c<ncol; ++c) {
      for (k=colind[c]; k<colind[c+1]; ++k) {
        r = row[k];
        if (r==c) {
          x[c] /= nz_r[k];
        } else {
          x[c] -= nz_r[k]*x[r];
        }
      }
    }
  } else {
    for (c=ncol-1; c>=0; --c) {
      for (k=colind[c+1]-1; k>=colind[c]; --k) {
        r=row[k];
        if (r==c) {
          x[r] /= nz_r[k];
        } else {
          x[r] -= nz_r[k]*x[c];
        }
      }
    }
  }
}
void casadi_qr_solve(casadi_real* x, casadi_int nrhs, casadi_int tr,
                     const casadi_int* sp_v, const casadi_real* v, const casadi_int* sp_r, const casadi_real* r,
                     const casadi_real* beta, const casadi_int* prinv, const casadi_int* pc, casadi_real* w) {
  casadi_int k, c, nrow_ext, ncol;
  nrow_ext = sp_v[0]; ncol = sp_v[1];
  for (k=0; k<nrhs; ++k) {
    if (tr) {
      for (c=0; c<ncol; ++c) w[c] = x[pc[c]];
      casadi_qr_trs(sp_r, r, w, 1);
      casadi_qr_mv(sp_v, v, beta, w, 0);
      for (c=0; c<ncol; ++c) x[c] = w[prinv[c]];
    } else {
      for (c=0; c<nrow_ext; ++c) w[c] = 0;
      for (c=0; c<ncol; ++c) w[prinv[c]] = x[c];
      casadi_qr_mv(sp_v, v, beta, w, 1);
      casadi_qr_trs(sp_r, r, w, 0);
      for (c=0; c<ncol; ++c) x[pc[c]] = w[c];
    }
    x += ncol;
  }
}
casadi_int casadi_qr_singular(casadi_real* rmin, casadi_int* irmin, const casadi_real* nz_r,
                             const casadi_int* sp_r, const casadi_int* pc, casadi_real eps) {
  casadi_real rd, rd_min;
  casadi_int ncol, c, nullity;
  const casadi_int* r_colind;
  nullity = 0;
  rd_min = 0;
  ncol = sp_r[1];
  r_colind = sp_r + 2;
  for (c=0; c<ncol; ++c) {
    rd = fabs(nz_r[r_colind[c+1]-1]);
    if (rd<eps) nullity++;
    if (c==0 || rd < rd_min) {
      rd_min = rd;
      if (rmin) *rmin = rd;
      if (irmin) *irmin = pc[c];
    }
  }
  return nullity;
}
void casadi_qr_colcomb(casadi_real* v, const casadi_real* nz_r, const casadi_int* sp_r,
                       const casadi_int* pc, casadi_real eps, casadi_int ind) {
  casadi_int ncol, r, c, k;
  const casadi_int *r_colind, *r_row;
  ncol = sp_r[1];
  r_colind = sp_r + 2;
  r_row = r_colind + ncol + 1;
  for (c=0; c<ncol; ++c) {
    if (fabs(nz_r[r_colind[c+1]-1])<eps && 0==ind--) {
      ind = c;
      break;
    }
  }
  casadi_clear(v, ncol);
  v[pc[ind]] = 1.;
  for (k=r_colind[ind]; k<r_colind[ind+1]-1; ++k) {
    v[pc[r_row[k]]] = -nz_r[k];
  }
  for (c=ind-1; c>=0; --c) {
    for (k=r_colind[c+1]-1; k>=r_colind[c]; --k) {
      r=r_row[k];
      if (r==c) {
        if (fabs(nz_r[k])<eps) {
          v[pc[r]] = 0;
        } else {
          v[pc[r]] /= nz_r[k];
        }
      } else {
        v[pc[r]] -= nz_r[k]*v[pc[c]];
      }
    }
  }
  casadi_scal(ncol, 1./sqrt(casadi_dot(ncol, v, v)), v);
}

void casadi_mtimes_dense(const casadi_real* x, casadi_int nrow_x, casadi_int ncol_x,
    const casadi_real* y, casadi_int ncol_y, casadi_real* z, casadi_int tr) {
  casadi_int i, j, k;
  if (tr) {
    for (i=0; i<ncol_y; ++i) {
      for (j=0; j<ncol_x; ++j) {
        for (k=0; k<nrow_x; ++k) {
          z[j + i*ncol_x] += x[k + j*nrow_x] * y[k + i*nrow_x];
        }
      }
    }
  } else {
    for (i=0; i<ncol_y; ++i) {
      for (j=0; j<nrow_x; ++j) {
        for (k=0; k<ncol_x; ++k) {
          z[j + i*nrow_x] += x[j + k*nrow_x] * y[k + i*ncol_x];
        }
      }
    }
  }
}

casadi_real casadi_norm_inf(casadi_int n, const casadi_real* x) {
  casadi_int i;
  casadi_real ret = 0;
  for (i=0; i<n; ++i) ret = casadi_fmax(ret, casadi_fabs(*x++));
  return ret;
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
static const casadi_int casadi_s20[3] = {2, 3, 1};
static const casadi_int casadi_s21[75] = 
  {36, 36, 0, 1, 2, 3, 4, 5,
  6, 7, 8, 9, 10, 11, 12, 13,
  14, 15, 16, 17, 18, 19, 20, 21,
  22, 23, 24, 25, 26, 27, 28, 29,
  30, 31, 32, 33, 34, 35, 36, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 18, 19, 20, 21, 22, 23, 24,
  25, 26, 27, 28, 29, 30, 31, 32,
  33, 34, 35};
static const casadi_int casadi_s22[759] = 
  {36, 36, 0, 19, 38, 57, 76, 95,
  114, 135, 156, 177, 198, 219, 240, 259,
  278, 297, 316, 335, 354, 375, 396, 417,
  438, 459, 480, 499, 518, 537, 556, 575,
  594, 615, 636, 657, 678, 699, 720, 0,
  6, 7, 8, 9, 10, 11, 18, 19,
  20, 21, 22, 23, 30, 31, 32, 33,
  34, 35, 1, 6, 7, 8, 9, 10,
  11, 18, 19, 20, 21, 22, 23, 30,
  31, 32, 33, 34, 35, 2, 6, 7,
  8, 9, 10, 11, 18, 19, 20, 21,
  22, 23, 30, 31, 32, 33, 34, 35,
  3, 6, 7, 8, 9, 10, 11, 18,
  19, 20, 21, 22, 23, 30, 31, 32,
  33, 34, 35, 4, 6, 7, 8, 9,
  10, 11, 18, 19, 20, 21, 22, 23,
  30, 31, 32, 33, 34, 35, 5, 6,
  7, 8, 9, 10, 11, 18, 19, 20,
  21, 22, 23, 30, 31, 32, 33, 34,
  35, 0, 6, 7, 8, 9, 10, 11,
  12, 18, 19, 20, 21, 22, 23, 24,
  30, 31, 32, 33, 34, 35, 1, 6,
  7, 8, 9, 10, 11, 13, 18, 19,
  20, 21, 22, 23, 25, 30, 31, 32,
  33, 34, 35, 2, 6, 7, 8, 9,
  10, 11, 14, 18, 19, 20, 21, 22,
  23, 26, 30, 31, 32, 33, 34, 35,
  3, 6, 7, 8, 9, 10, 11, 15,
  18, 19, 20, 21, 22, 23, 27, 30,
  31, 32, 33, 34, 35, 4, 6, 7,
  8, 9, 10, 11, 16, 18, 19, 20,
  21, 22, 23, 28, 30, 31, 32, 33,
  34, 35, 5, 6, 7, 8, 9, 10,
  11, 17, 18, 19, 20, 21, 22, 23,
  29, 30, 31, 32, 33, 34, 35, 6,
  7, 8, 9, 10, 11, 12, 18, 19,
  20, 21, 22, 23, 30, 31, 32, 33,
  34, 35, 6, 7, 8, 9, 10, 11,
  13, 18, 19, 20, 21, 22, 23, 30,
  31, 32, 33, 34, 35, 6, 7, 8,
  9, 10, 11, 14, 18, 19, 20, 21,
  22, 23, 30, 31, 32, 33, 34, 35,
  6, 7, 8, 9, 10, 11, 15, 18,
  19, 20, 21, 22, 23, 30, 31, 32,
  33, 34, 35, 6, 7, 8, 9, 10,
  11, 16, 18, 19, 20, 21, 22, 23,
  30, 31, 32, 33, 34, 35, 6, 7,
  8, 9, 10, 11, 17, 18, 19, 20,
  21, 22, 23, 30, 31, 32, 33, 34,
  35, 0, 6, 7, 8, 9, 10, 11,
  12, 18, 19, 20, 21, 22, 23, 24,
  30, 31, 32, 33, 34, 35, 1, 6,
  7, 8, 9, 10, 11, 13, 18, 19,
  20, 21, 22, 23, 25, 30, 31, 32,
  33, 34, 35, 2, 6, 7, 8, 9,
  10, 11, 14, 18, 19, 20, 21, 22,
  23, 26, 30, 31, 32, 33, 34, 35,
  3, 6, 7, 8, 9, 10, 11, 15,
  18, 19, 20, 21, 22, 23, 27, 30,
  31, 32, 33, 34, 35, 4, 6, 7,
  8, 9, 10, 11, 16, 18, 19, 20,
  21, 22, 23, 28, 30, 31, 32, 33,
  34, 35, 5, 6, 7, 8, 9, 10,
  11, 17, 18, 19, 20, 21, 22, 23,
  29, 30, 31, 32, 33, 34, 35, 6,
  7, 8, 9, 10, 11, 18, 19, 20,
  21, 22, 23, 24, 30, 31, 32, 33,
  34, 35, 6, 7, 8, 9, 10, 11,
  18, 19, 20, 21, 22, 23, 25, 30,
  31, 32, 33, 34, 35, 6, 7, 8,
  9, 10, 11, 18, 19, 20, 21, 22,
  23, 26, 30, 31, 32, 33, 34, 35,
  6, 7, 8, 9, 10, 11, 18, 19,
  20, 21, 22, 23, 27, 30, 31, 32,
  33, 34, 35, 6, 7, 8, 9, 10,
  11, 18, 19, 20, 21, 22, 23, 28,
  30, 31, 32, 33, 34, 35, 6, 7,
  8, 9, 10, 11, 18, 19, 20, 21,
  22, 23, 29, 30, 31, 32, 33, 34,
  35, 0, 6, 7, 8, 9, 10, 11,
  12, 18, 19, 20, 21, 22, 23, 24,
  30, 31, 32, 33, 34, 35, 1, 6,
  7, 8, 9, 10, 11, 13, 18, 19,
  20, 21, 22, 23, 25, 30, 31, 32,
  33, 34, 35, 2, 6, 7, 8, 9,
  10, 11, 14, 18, 19, 20, 21, 22,
  23, 26, 30, 31, 32, 33, 34, 35,
  3, 6, 7, 8, 9, 10, 11, 15,
  18, 19, 20, 21, 22, 23, 27, 30,
  31, 32, 33, 34, 35, 4, 6, 7,
  8, 9, 10, 11, 16, 18, 19, 20,
  21, 22, 23, 28, 30, 31, 32, 33,
  34, 35, 5, 6, 7, 8, 9, 10,
  11, 17, 18, 19, 20, 21, 22, 23,
  29, 30, 31, 32, 33, 34, 35};
static const casadi_int casadi_s23[741] = 
  {36, 36, 0, 18, 36, 54, 72, 90,
  108, 129, 150, 171, 192, 213, 234, 252,
  270, 288, 306, 324, 342, 363, 384, 405,
  426, 447, 468, 486, 504, 522, 540, 558,
  576, 597, 618, 639, 660, 681, 702, 6,
  7, 8, 9, 10, 11, 18, 19, 20,
  21, 22, 23, 30, 31, 32, 33, 34,
  35, 6, 7, 8, 9, 10, 11, 18,
  19, 20, 21, 22, 23, 30, 31, 32,
  33, 34, 35, 6, 7, 8, 9, 10,
  11, 18, 19, 20, 21, 22, 23, 30,
  31, 32, 33, 34, 35, 6, 7, 8,
  9, 10, 11, 18, 19, 20, 21, 22,
  23, 30, 31, 32, 33, 34, 35, 6,
  7, 8, 9, 10, 11, 18, 19, 20,
  21, 22, 23, 30, 31, 32, 33, 34,
  35, 6, 7, 8, 9, 10, 11, 18,
  19, 20, 21, 22, 23, 30, 31, 32,
  33, 34, 35, 0, 6, 7, 8, 9,
  10, 11, 12, 18, 19, 20, 21, 22,
  23, 24, 30, 31, 32, 33, 34, 35,
  1, 6, 7, 8, 9, 10, 11, 13,
  18, 19, 20, 21, 22, 23, 25, 30,
  31, 32, 33, 34, 35, 2, 6, 7,
  8, 9, 10, 11, 14, 18, 19, 20,
  21, 22, 23, 26, 30, 31, 32, 33,
  34, 35, 3, 6, 7, 8, 9, 10,
  11, 15, 18, 19, 20, 21, 22, 23,
  27, 30, 31, 32, 33, 34, 35, 4,
  6, 7, 8, 9, 10, 11, 16, 18,
  19, 20, 21, 22, 23, 28, 30, 31,
  32, 33, 34, 35, 5, 6, 7, 8,
  9, 10, 11, 17, 18, 19, 20, 21,
  22, 23, 29, 30, 31, 32, 33, 34,
  35, 6, 7, 8, 9, 10, 11, 18,
  19, 20, 21, 22, 23, 30, 31, 32,
  33, 34, 35, 6, 7, 8, 9, 10,
  11, 18, 19, 20, 21, 22, 23, 30,
  31, 32, 33, 34, 35, 6, 7, 8,
  9, 10, 11, 18, 19, 20, 21, 22,
  23, 30, 31, 32, 33, 34, 35, 6,
  7, 8, 9, 10, 11, 18, 19, 20,
  21, 22, 23, 30, 31, 32, 33, 34,
  35, 6, 7, 8, 9, 10, 11, 18,
  19, 20, 21, 22, 23, 30, 31, 32,
  33, 34, 35, 6, 7, 8, 9, 10,
  11, 18, 19, 20, 21, 22, 23, 30,
  31, 32, 33, 34, 35, 0, 6, 7,
  8, 9, 10, 11, 12, 18, 19, 20,
  21, 22, 23, 24, 30, 31, 32, 33,
  34, 35, 1, 6, 7, 8, 9, 10,
  11, 13, 18, 19, 20, 21, 22, 23,
  25, 30, 31, 32, 33, 34, 35, 2,
  6, 7, 8, 9, 10, 11, 14, 18,
  19, 20, 21, 22, 23, 26, 30, 31,
  32, 33, 34, 35, 3, 6, 7, 8,
  9, 10, 11, 15, 18, 19, 20, 21,
  22, 23, 27, 30, 31, 32, 33, 34,
  35, 4, 6, 7, 8, 9, 10, 11,
  16, 18, 19, 20, 21, 22, 23, 28,
  30, 31, 32, 33, 34, 35, 5, 6,
  7, 8, 9, 10, 11, 17, 18, 19,
  20, 21, 22, 23, 29, 30, 31, 32,
  33, 34, 35, 6, 7, 8, 9, 10,
  11, 18, 19, 20, 21, 22, 23, 30,
  31, 32, 33, 34, 35, 6, 7, 8,
  9, 10, 11, 18, 19, 20, 21, 22,
  23, 30, 31, 32, 33, 34, 35, 6,
  7, 8, 9, 10, 11, 18, 19, 20,
  21, 22, 23, 30, 31, 32, 33, 34,
  35, 6, 7, 8, 9, 10, 11, 18,
  19, 20, 21, 22, 23, 30, 31, 32,
  33, 34, 35, 6, 7, 8, 9, 10,
  11, 18, 19, 20, 21, 22, 23, 30,
  31, 32, 33, 34, 35, 6, 7, 8,
  9, 10, 11, 18, 19, 20, 21, 22,
  23, 30, 31, 32, 33, 34, 35, 0,
  6, 7, 8, 9, 10, 11, 12, 18,
  19, 20, 21, 22, 23, 24, 30, 31,
  32, 33, 34, 35, 1, 6, 7, 8,
  9, 10, 11, 13, 18, 19, 20, 21,
  22, 23, 25, 30, 31, 32, 33, 34,
  35, 2, 6, 7, 8, 9, 10, 11,
  14, 18, 19, 20, 21, 22, 23, 26,
  30, 31, 32, 33, 34, 35, 3, 6,
  7, 8, 9, 10, 11, 15, 18, 19,
  20, 21, 22, 23, 27, 30, 31, 32,
  33, 34, 35, 4, 6, 7, 8, 9,
  10, 11, 16, 18, 19, 20, 21, 22,
  23, 28, 30, 31, 32, 33, 34, 35,
  5, 6, 7, 8, 9, 10, 11, 17,
  18, 19, 20, 21, 22, 23, 29, 30,
  31, 32, 33, 34, 35};
static const casadi_int casadi_s24[36] = 
  {0, 19, 20, 21, 22, 23, 1, 2,
  3, 4, 5, 6, 24, 26, 28, 30,
  32, 34, 7, 8, 9, 10, 11, 12,
  25, 27, 29, 31, 33, 35, 13, 14,
  15, 16, 17, 18};
static const casadi_int casadi_s25[36] = 
  {0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 15,
  16, 17, 18, 19, 20, 21, 22, 23,
  24, 25, 26, 27, 28, 29, 30, 31,
  32, 33, 34, 35};
static const casadi_int casadi_s26[588] = 
  {36, 36, 0, 19, 38, 57, 76, 95,
  114, 134, 155, 177, 200, 224, 249, 273,
  296, 318, 339, 359, 378, 396, 413, 429,
  444, 458, 471, 483, 494, 504, 513, 521,
  528, 534, 539, 543, 546, 548, 549, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 18, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 18, 19, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 18, 19, 20,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 18,
  19, 20, 21, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 18, 19, 20, 21, 22, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 18, 19, 20, 21, 22,
  23, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 18, 19, 20,
  21, 22, 23, 24, 25, 7, 8, 9,
  10, 11, 12, 13, 14, 15, 16, 17,
  18, 19, 20, 21, 22, 23, 24, 25,
  26, 27, 8, 9, 10, 11, 12, 13,
  14, 15, 16, 17, 18, 19, 20, 21,
  22, 23, 24, 25, 26, 27, 28, 29,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 18, 19, 20, 21, 22, 23, 24,
  25, 26, 27, 28, 29, 30, 31, 10,
  11, 12, 13, 14, 15, 16, 17, 18,
  19, 20, 21, 22, 23, 24, 25, 26,
  27, 28, 29, 30, 31, 32, 33, 11,
  12, 13, 14, 15, 16, 17, 18, 19,
  20, 21, 22, 23, 24, 25, 26, 27,
  28, 29, 30, 31, 32, 33, 34, 35,
  12, 13, 14, 15, 16, 17, 18, 19,
  20, 21, 22, 23, 24, 25, 26, 27,
  28, 29, 30, 31, 32, 33, 34, 35,
  13, 14, 15, 16, 17, 18, 19, 20,
  21, 22, 23, 24, 25, 26, 27, 28,
  29, 30, 31, 32, 33, 34, 35, 14,
  15, 16, 17, 18, 19, 20, 21, 22,
  23, 24, 25, 26, 27, 28, 29, 30,
  31, 32, 33, 34, 35, 15, 16, 17,
  18, 19, 20, 21, 22, 23, 24, 25,
  26, 27, 28, 29, 30, 31, 32, 33,
  34, 35, 16, 17, 18, 19, 20, 21,
  22, 23, 24, 25, 26, 27, 28, 29,
  30, 31, 32, 33, 34, 35, 17, 18,
  19, 20, 21, 22, 23, 24, 25, 26,
  27, 28, 29, 30, 31, 32, 33, 34,
  35, 18, 19, 20, 21, 22, 23, 24,
  25, 26, 27, 28, 29, 30, 31, 32,
  33, 34, 35, 19, 20, 21, 22, 23,
  24, 25, 26, 27, 28, 29, 30, 31,
  32, 33, 34, 35, 20, 21, 22, 23,
  24, 25, 26, 27, 28, 29, 30, 31,
  32, 33, 34, 35, 21, 22, 23, 24,
  25, 26, 27, 28, 29, 30, 31, 32,
  33, 34, 35, 22, 23, 24, 25, 26,
  27, 28, 29, 30, 31, 32, 33, 34,
  35, 23, 24, 25, 26, 27, 28, 29,
  30, 31, 32, 33, 34, 35, 24, 25,
  26, 27, 28, 29, 30, 31, 32, 33,
  34, 35, 25, 26, 27, 28, 29, 30,
  31, 32, 33, 34, 35, 26, 27, 28,
  29, 30, 31, 32, 33, 34, 35, 27,
  28, 29, 30, 31, 32, 33, 34, 35,
  28, 29, 30, 31, 32, 33, 34, 35,
  29, 30, 31, 32, 33, 34, 35, 30,
  31, 32, 33, 34, 35, 31, 32, 33,
  34, 35, 32, 33, 34, 35, 33, 34,
  35, 34, 35, 35};
static const casadi_int casadi_s27[705] = 
  {36, 36, 0, 1, 3, 6, 10, 15,
  21, 28, 36, 45, 55, 66, 78, 91,
  105, 120, 136, 153, 171, 190, 210, 231,
  253, 276, 300, 325, 351, 378, 406, 435,
  465, 496, 528, 561, 595, 630, 666, 0,
  0, 1, 0, 1, 2, 0, 1, 2,
  3, 0, 1, 2, 3, 4, 0, 1,
  2, 3, 4, 5, 0, 1, 2, 3,
  4, 5, 6, 0, 1, 2, 3, 4,
  5, 6, 7, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 0, 1, 2, 3,
  4, 5, 6, 7, 8, 9, 0, 1,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 0, 1, 2, 3, 4, 5,
  6, 7, 8, 9, 10, 11, 12, 13,
  0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 15,
  16, 17, 0, 1, 2, 3, 4, 5,
  6, 7, 8, 9, 10, 11, 12, 13,
  14, 15, 16, 17, 18, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 18,
  19, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 18, 19, 20, 0, 1,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 11, 12, 13, 14, 15, 16, 17,
  18, 19, 20, 21, 0, 1, 2, 3,
  4, 5, 6, 7, 8, 9, 10, 11,
  12, 13, 14, 15, 16, 17, 18, 19,
  20, 21, 22, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 18, 19, 20,
  21, 22, 23, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 18, 19, 20,
  21, 22, 23, 24, 0, 1, 2, 3,
  4, 5, 6, 7, 8, 9, 10, 11,
  12, 13, 14, 15, 16, 17, 18, 19,
  20, 21, 22, 23, 24, 25, 0, 1,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 11, 12, 13, 14, 15, 16, 17,
  18, 19, 20, 21, 22, 23, 24, 25,
  26, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 18, 19, 20, 21, 22,
  23, 24, 25, 26, 27, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 18,
  19, 20, 21, 22, 23, 24, 25, 26,
  27, 28, 0, 1, 2, 3, 4, 5,
  6, 7, 8, 9, 10, 11, 12, 13,
  14, 15, 16, 17, 18, 19, 20, 21,
  22, 23, 24, 25, 26, 27, 28, 29,
  0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 15,
  16, 17, 18, 19, 20, 21, 22, 23,
  24, 25, 26, 27, 28, 29, 30, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 18, 19, 20, 21, 22, 23, 24,
  25, 26, 27, 28, 29, 30, 31, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 18, 19, 20, 21, 22, 23, 24,
  25, 26, 27, 28, 29, 30, 31, 32,
  0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 15,
  16, 17, 18, 19, 20, 21, 22, 23,
  24, 25, 26, 27, 28, 29, 30, 31,
  32, 33, 0, 1, 2, 3, 4, 5,
  6, 7, 8, 9, 10, 11, 12, 13,
  14, 15, 16, 17, 18, 19, 20, 21,
  22, 23, 24, 25, 26, 27, 28, 29,
  30, 31, 32, 33, 34, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 18,
  19, 20, 21, 22, 23, 24, 25, 26,
  27, 28, 29, 30, 31, 32, 33, 34,
  35};

static const casadi_real casadi_c0[1296] = 
  {1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 1., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 1., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 1.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 1., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 1., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 1., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 1., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 1., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 1., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 1.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 1., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 1., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 1., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 1., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 1., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 1., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 1.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 1., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 1., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 1., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 1., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 1., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 1., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 1.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 1., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 1., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 1., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 1., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 1., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 1., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 1.};
static const casadi_real casadi_c1[9] = 
  {1.9681547722366044e-01, 3.9442431473908729e-01, 3.7640306270046725e-01, -6.5535425850198378e-02, 2.9207341166522843e-01, 5.1248582618842164e-01, 2.3770974348220151e-02, -4.1548752125997922e-02,
  1.1111111111111110e-01};
static const casadi_real casadi_c2[9] = 
  {1.9681547722366044e-01, -6.5535425850198378e-02, 2.3770974348220151e-02, 3.9442431473908729e-01, 2.9207341166522843e-01, -4.1548752125997922e-02, 3.7640306270046725e-01, 5.1248582618842164e-01,
  1.1111111111111110e-01};

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
  a03=1.0000000000000000e-03;
  a04=arg[2]? arg[2][38] : 0;
  a03=(a03*a04);
  a05=casadi_fmax(a02,a03);
  a06=arg[2]? arg[2][21] : 0;
  a07=arg[0]? arg[0][6] : 0;
  a08=(a06*a07);
  a09=-9.9999999999999995e-07;
  a10=(a09*a06);
  a11=9.9999999999999995e-07;
  a12=arg[2]? arg[2][20] : 0;
  a13=(a11*a12);
  a10=(a10+a13);
  a10=casadi_sq(a10);
  a13=arg[0]? arg[0][2] : 0;
  a14=casadi_sq(a13);
  a15=arg[0]? arg[0][3] : 0;
  a16=casadi_sq(a15);
  a14=(a14+a16);
  a10=casadi_fmax(a10,a14);
  a14=-5.0000000000000000e-01;
  a16=pow(a10,a14);
  a17=(a16*a13);
  a18=arg[0]? arg[0][9] : 0;
  a17=(a17*a18);
  a08=(a08+a17);
  a17=(a16*a15);
  a19=arg[0]? arg[0][8] : 0;
  a17=(a17*a19);
  a08=(a08-a17);
  a17=casadi_fabs(a08);
  a05=casadi_fmax(a05,a17);
  a20=(a01/a05);
  a20=(a20*a08);
  a21=0.;
  a10=sqrt(a10);
  a10=(a06+a10);
  a10=(a10-a12);
  a22=(a21<a10);
  a23=1.3333333333333333e+00;
  a24=(a12*a06);
  a12=(a12-a06);
  a24=(a24/a12);
  a24=sqrt(a24);
  a24=(a23*a24);
  a12=1.;
  a25=arg[2]? arg[2][23] : 0;
  a25=casadi_sq(a25);
  a25=(a12-a25);
  a26=arg[2]? arg[2][22] : 0;
  a25=(a25/a26);
  a26=arg[2]? arg[2][25] : 0;
  a26=casadi_sq(a26);
  a26=(a12-a26);
  a27=arg[2]? arg[2][24] : 0;
  a26=(a26/a27);
  a25=(a25+a26);
  a24=(a24/a25);
  a25=7.5000000000000000e-01;
  a26=-7.5000000000000000e-01;
  a27=arg[2]? arg[2][34] : 0;
  a27=casadi_sq(a27);
  a26=(a26*a27);
  a25=(a25+a26);
  a26=arg[3]? arg[3][0] : 0;
  a27=arg[2]? arg[2][35] : 0;
  a26=casadi_fmax(a26,a27);
  a26=(a25/a26);
  a28=(a16*a13);
  a28=(a28*a19);
  a19=(a16*a15);
  a19=(a19*a18);
  a28=(a28+a19);
  a26=(a26*a28);
  a26=(a12+a26);
  a24=(a24*a26);
  a26=1.0000000000000000e-300;
  a10=casadi_fmax(a26,a10);
  a28=arg[2]? arg[2][33] : 0;
  a10=pow(a10,a28);
  a24=(a24*a10);
  a22=(a22?a24:0);
  a22=casadi_fmax(a21,a22);
  a20=(a20*a22);
  a17=(a17-a02);
  a04=(a04-a02);
  a17=(a17/a04);
  a17=casadi_fmax(a21,a17);
  a17=casadi_fmin(a12,a17);
  a20=(a20*a17);
  a20=(a20*a06);
  a00=(a00-a20);
  a03=casadi_fmax(a02,a03);
  a20=arg[2]? arg[2][26] : 0;
  a06=(a20*a07);
  a24=arg[2]? arg[2][27] : 0;
  a10=arg[0]? arg[0][7] : 0;
  a10=(a07+a10);
  a19=(a24*a10);
  a06=(a06-a19);
  a09=(a09*a24);
  a11=(a11*a20);
  a09=(a09+a11);
  a09=casadi_sq(a09);
  a11=arg[0]? arg[0][4] : 0;
  a19=casadi_sq(a11);
  a18=arg[0]? arg[0][5] : 0;
  a29=casadi_sq(a18);
  a19=(a19+a29);
  a09=casadi_fmax(a09,a19);
  a14=pow(a09,a14);
  a19=(a14*a18);
  a29=arg[0]? arg[0][10] : 0;
  a19=(a19*a29);
  a06=(a06+a19);
  a19=(a14*a11);
  a30=arg[0]? arg[0][11] : 0;
  a19=(a19*a30);
  a06=(a06-a19);
  a06=casadi_fabs(a06);
  a03=casadi_fmax(a03,a06);
  a19=(a01/a03);
  a31=(a24*a10);
  a32=(a20*a07);
  a31=(a31-a32);
  a32=(a14*a11);
  a32=(a32*a30);
  a31=(a31+a32);
  a32=(a14*a18);
  a32=(a32*a29);
  a31=(a31-a32);
  a19=(a19*a31);
  a09=sqrt(a09);
  a09=(a24+a09);
  a09=(a09-a20);
  a32=(a21<a09);
  a33=(a20*a24);
  a34=(a20-a24);
  a33=(a33/a34);
  a33=sqrt(a33);
  a23=(a23*a33);
  a33=arg[2]? arg[2][29] : 0;
  a33=casadi_sq(a33);
  a33=(a12-a33);
  a34=arg[2]? arg[2][28] : 0;
  a33=(a33/a34);
  a34=arg[2]? arg[2][31] : 0;
  a34=casadi_sq(a34);
  a34=(a12-a34);
  a35=arg[2]? arg[2][30] : 0;
  a34=(a34/a35);
  a33=(a33+a34);
  a23=(a23/a33);
  a33=arg[3]? arg[3][1] : 0;
  a33=casadi_fmax(a33,a27);
  a25=(a25/a33);
  a33=(a14*a11);
  a33=(a33*a29);
  a29=(a14*a18);
  a29=(a29*a30);
  a33=(a33+a29);
  a25=(a25*a33);
  a25=(a12+a25);
  a23=(a23*a25);
  a26=casadi_fmax(a26,a09);
  a26=pow(a26,a28);
  a23=(a23*a26);
  a32=(a32?a23:0);
  a32=casadi_fmax(a21,a32);
  a19=(a19*a32);
  a06=(a06-a02);
  a06=(a06/a04);
  a21=casadi_fmax(a21,a06);
  a12=casadi_fmin(a12,a21);
  a19=(a19*a12);
  a24=(a19*a24);
  a00=(a00-a24);
  a19=(a19*a20);
  a00=(a00+a19);
  a19=arg[2]? arg[2][17] : 0;
  a20=arg[2]? arg[2][9] : 0;
  a21=(a19*a20);
  a06=arg[2]? arg[2][4] : 0;
  a04=arg[2]? arg[2][19] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a23=(a04+a02);
  a26=sin(a23);
  a28=(a06*a26);
  a09=arg[2]? arg[2][11] : 0;
  a25=(a04+a02);
  a33=arg[0]? arg[0][1] : 0;
  a25=(a25+a33);
  a29=sin(a25);
  a30=(a09*a29);
  a30=(a28+a30);
  a21=(a21*a30);
  a00=(a00-a21);
  a21=arg[2]? arg[2][13] : 0;
  a27=(a19*a21);
  a34=arg[2]? arg[2][8] : 0;
  a35=(a34*a29);
  a36=(a28+a35);
  a37=arg[2]? arg[2][15] : 0;
  a38=arg[2]? arg[2][32] : 0;
  a04=(a04+a38);
  a04=(a04+a02);
  a04=(a04+a33);
  a33=sin(a04);
  a02=(a37*a33);
  a36=(a36+a02);
  a27=(a27*a36);
  a00=(a00-a27);
  a27=arg[2]? arg[2][16] : 0;
  a38=(a19*a27);
  a28=(a28+a35);
  a39=arg[2]? arg[2][12] : 0;
  a40=(a39*a33);
  a28=(a28+a40);
  a38=(a38*a28);
  a00=(a00-a38);
  a38=arg[2]? arg[2][18] : 0;
  a41=(a38*a20);
  a23=cos(a23);
  a42=(a06*a23);
  a25=cos(a25);
  a43=(a09*a25);
  a43=(a42+a43);
  a41=(a41*a43);
  a00=(a00+a41);
  a41=(a38*a21);
  a44=(a34*a25);
  a45=(a42+a44);
  a04=cos(a04);
  a46=(a37*a04);
  a45=(a45+a46);
  a41=(a41*a45);
  a00=(a00+a41);
  a41=(a38*a27);
  a42=(a42+a44);
  a47=(a39*a04);
  a42=(a42+a47);
  a41=(a41*a42);
  a00=(a00+a41);
  a43=(a20*a43);
  a07=casadi_sq(a07);
  a41=(a06*a07);
  a41=(a41*a26);
  a10=casadi_sq(a10);
  a48=(a09*a10);
  a48=(a48*a29);
  a48=(a41+a48);
  a43=(a43*a48);
  a00=(a00+a43);
  a30=(a20*a30);
  a06=(a06*a07);
  a06=(a06*a23);
  a43=(a09*a10);
  a43=(a43*a25);
  a43=(a06+a43);
  a30=(a30*a43);
  a00=(a00-a30);
  a45=(a21*a45);
  a30=(a34*a10);
  a30=(a30*a29);
  a49=(a41+a30);
  a50=(a37*a10);
  a50=(a50*a33);
  a49=(a49+a50);
  a45=(a45*a49);
  a00=(a00+a45);
  a36=(a21*a36);
  a34=(a34*a10);
  a34=(a34*a25);
  a45=(a06+a34);
  a37=(a37*a10);
  a37=(a37*a04);
  a45=(a45+a37);
  a36=(a36*a45);
  a00=(a00-a36);
  a42=(a27*a42);
  a41=(a41+a30);
  a30=(a39*a10);
  a30=(a30*a33);
  a41=(a41+a30);
  a42=(a42*a41);
  a00=(a00+a42);
  a28=(a27*a28);
  a06=(a06+a34);
  a39=(a39*a10);
  a39=(a39*a04);
  a06=(a06+a39);
  a28=(a28*a06);
  a00=(a00-a28);
  a28=arg[2]? arg[2][7] : 0;
  a39=(a28*a38);
  a04=arg[2]? arg[2][5] : 0;
  a39=(a39*a04);
  a39=(a39*a23);
  a00=(a00+a39);
  a39=(a28*a19);
  a39=(a39*a04);
  a39=(a39*a26);
  a00=(a00-a39);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[1]? arg[1][1] : 0;
  a00=(a00-a24);
  a24=(a19*a21);
  a02=(a35+a02);
  a24=(a24*a02);
  a00=(a00-a24);
  a24=(a19*a27);
  a35=(a35+a40);
  a24=(a24*a35);
  a00=(a00-a24);
  a24=(a38*a21);
  a46=(a44+a46);
  a24=(a24*a46);
  a00=(a00+a24);
  a24=(a38*a27);
  a44=(a44+a47);
  a24=(a24*a44);
  a00=(a00+a24);
  a46=(a21*a46);
  a46=(a46*a49);
  a00=(a00+a46);
  a02=(a21*a02);
  a02=(a02*a45);
  a00=(a00-a02);
  a44=(a27*a44);
  a44=(a44*a41);
  a00=(a00+a44);
  a35=(a27*a35);
  a35=(a35*a06);
  a00=(a00-a35);
  a35=(a09*a38);
  a35=(a35*a20);
  a35=(a35*a25);
  a00=(a00+a35);
  a35=(a09*a20);
  a35=(a35*a43);
  a35=(a35*a29);
  a00=(a00-a35);
  a35=(a09*a19);
  a35=(a35*a20);
  a35=(a35*a29);
  a00=(a00-a35);
  a09=(a09*a20);
  a09=(a09*a48);
  a09=(a09*a25);
  a00=(a00+a09);
  if (res[0]!=0) res[0][1]=a00;
  a00=(a01*a16);
  a00=(a00/a05);
  a00=(a00*a08);
  a00=(a00*a22);
  a00=(a00*a17);
  a00=(a00*a15);
  a09=(a16*a22);
  a09=(a09*a13);
  a00=(a00-a09);
  a09=(a19*a04);
  a00=(a00+a09);
  a09=(a19*a20);
  a00=(a00+a09);
  a25=(a19*a21);
  a00=(a00+a25);
  a19=(a19*a27);
  a00=(a00+a19);
  a43=(a20*a43);
  a00=(a00+a43);
  a45=(a21*a45);
  a00=(a00+a45);
  a06=(a27*a06);
  a00=(a00+a06);
  a35=(a28*a04);
  a35=(a35*a07);
  a35=(a35*a23);
  a00=(a00+a35);
  if (res[0]!=0) res[0][2]=a00;
  a00=(a38*a04);
  a35=(a16*a22);
  a35=(a35*a15);
  a16=(a01*a16);
  a16=(a16/a05);
  a16=(a16*a08);
  a16=(a16*a22);
  a16=(a16*a17);
  a16=(a16*a13);
  a35=(a35+a16);
  a00=(a00-a35);
  a35=(a38*a20);
  a00=(a00+a35);
  a16=(a38*a21);
  a00=(a00+a16);
  a38=(a38*a27);
  a00=(a00+a38);
  a20=(a20*a48);
  a00=(a00+a20);
  a21=(a21*a49);
  a00=(a00+a21);
  a27=(a27*a41);
  a00=(a00+a27);
  a28=(a28*a04);
  a28=(a28*a07);
  a28=(a28*a26);
  a00=(a00+a28);
  if (res[0]!=0) res[0][3]=a00;
  a00=(a01*a14);
  a00=(a00/a03);
  a00=(a00*a31);
  a00=(a00*a32);
  a00=(a00*a12);
  a00=(a00*a18);
  a28=(a14*a32);
  a28=(a28*a11);
  a00=(a00-a28);
  a00=(a00+a09);
  a00=(a00+a25);
  a00=(a00+a19);
  a00=(a00+a43);
  a00=(a00+a45);
  a00=(a00+a06);
  if (res[0]!=0) res[0][4]=a00;
  a00=(a14*a32);
  a00=(a00*a18);
  a01=(a01*a14);
  a01=(a01/a03);
  a01=(a01*a31);
  a01=(a01*a32);
  a01=(a01*a12);
  a01=(a01*a11);
  a00=(a00+a01);
  a35=(a35-a00);
  a35=(a35+a16);
  a35=(a35+a38);
  a35=(a35+a20);
  a35=(a35+a21);
  a35=(a35+a27);
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
  casadi_real a288, a289, a290, a291, a292, a293, a294, a295;
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
  a043=(a056-a092);
  a013=(a013/a043);
  a046=casadi_fmax(a064,a013);
  a036=casadi_fmin(a126,a046);
  a091=sqrt(a054);
  a095=(a066+a091);
  a095=(a095-a018);
  a127=(a064<a095);
  a128=1.3333333333333333e+00;
  a129=(a018*a066);
  a130=(a018-a066);
  a129=(a129/a130);
  a131=sqrt(a129);
  a132=(a128*a131);
  a133=arg[3]? arg[3][23] : 0;
  a134=casadi_sq(a133);
  a134=(a126-a134);
  a135=arg[3]? arg[3][22] : 0;
  a134=(a134/a135);
  a136=arg[3]? arg[3][25] : 0;
  a137=casadi_sq(a136);
  a137=(a126-a137);
  a138=arg[3]? arg[3][24] : 0;
  a137=(a137/a138);
  a139=(a134+a137);
  a132=(a132/a139);
  a140=7.5000000000000000e-01;
  a141=-7.5000000000000000e-01;
  a142=arg[3]? arg[3][34] : 0;
  a143=casadi_sq(a142);
  a143=(a141*a143);
  a140=(a140+a143);
  a143=arg[4]? arg[4][0] : 0;
  a144=arg[3]? arg[3][35] : 0;
  a145=casadi_fmax(a143,a144);
  a146=(a140/a145);
  a147=(a016*a055);
  a148=(a147*a110);
  a149=(a016*a050);
  a150=(a149*a023);
  a148=(a148+a150);
  a150=(a146*a148);
  a150=(a126+a150);
  a151=(a132*a150);
  a152=1.0000000000000000e-300;
  a153=casadi_fmax(a152,a095);
  a154=arg[3]? arg[3][33] : 0;
  a155=pow(a153,a154);
  a156=(a151*a155);
  a156=(a127?a156:0);
  a157=casadi_fmax(a064,a156);
  a158=arg[3]? arg[3][36] : 0;
  a159=1.0000000000000000e-03;
  a056=(a159*a056);
  a160=casadi_fmax(a092,a056);
  a161=casadi_fmax(a160,a106);
  a162=(a158/a161);
  a163=-1.5000000000000000e+00;
  a164=pow(a054,a163);
  a164=(a109*a164);
  a165=(a076<=a014);
  a166=(a014<=a076);
  a166=(a166+a165);
  a165=(a165/a166);
  a166=(2.*a055);
  a166=(a165*a166);
  a167=(a164*a166);
  a168=(a055*a167);
  a168=(a168+a016);
  a168=(a023*a168);
  a169=(a050*a167);
  a169=(a110*a169);
  a168=(a168-a169);
  a169=(a162*a168);
  a170=(a162/a161);
  a171=(a160<=a106);
  a172=(a106<=a160);
  a172=(a172+a171);
  a171=(a171/a172);
  a172=casadi_sign(a075);
  a173=(a172*a168);
  a174=(a171*a173);
  a175=(a170*a174);
  a175=(a075*a175);
  a169=(a169-a175);
  a169=(a157*a169);
  a175=(a162*a075);
  a176=(a064<=a156);
  a177=(a156<=a064);
  a177=(a177+a176);
  a176=(a176/a177);
  a177=(a055*a167);
  a177=(a177+a016);
  a177=(a110*a177);
  a178=(a050*a167);
  a178=(a023*a178);
  a177=(a177+a178);
  a177=(a146*a177);
  a177=(a132*a177);
  a177=(a155*a177);
  a178=(a154-a126);
  a178=pow(a153,a178);
  a178=(a154*a178);
  a179=(a152<=a095);
  a180=(a095<=a152);
  a180=(a180+a179);
  a179=(a179/a180);
  a180=(2.*a091);
  a166=(a166/a180);
  a166=(a179*a166);
  a166=(a178*a166);
  a166=(a151*a166);
  a177=(a177+a166);
  a177=(a176*a177);
  a166=(a175*a177);
  a166=(a127?a166:0);
  a169=(a169+a166);
  a169=(a036*a169);
  a166=(a175*a157);
  a181=(a046<=a126);
  a182=(a126<=a046);
  a182=(a182+a181);
  a181=(a181/a182);
  a182=(a064<=a013);
  a183=(a013<=a064);
  a183=(a183+a182);
  a182=(a182/a183);
  a173=(a173/a043);
  a173=(a182*a173);
  a173=(a181*a173);
  a183=(a166*a173);
  a169=(a169+a183);
  a169=(a066*a169);
  if (res[0]!=0) res[0][12]=a169;
  a169=(a158*a167);
  a169=(a169/a161);
  a183=(a158*a016);
  a183=(a183/a161);
  a184=(a183/a161);
  a185=(a184*a174);
  a169=(a169-a185);
  a169=(a075*a169);
  a185=(a183*a168);
  a169=(a169+a185);
  a169=(a157*a169);
  a185=(a183*a075);
  a186=(a185*a177);
  a186=(a127?a186:0);
  a169=(a169+a186);
  a169=(a036*a169);
  a186=(a185*a157);
  a187=(a186*a173);
  a169=(a169+a187);
  a169=(a050*a169);
  a187=(a157*a167);
  a188=(a016*a177);
  a188=(a127?a188:0);
  a187=(a187+a188);
  a187=(a055*a187);
  a188=(a016*a157);
  a187=(a187+a188);
  a169=(a169-a187);
  a169=(-a169);
  if (res[0]!=0) res[0][13]=a169;
  a169=(a157*a167);
  a187=(a016*a177);
  a187=(a127?a187:0);
  a169=(a169+a187);
  a169=(a050*a169);
  a167=(a158*a167);
  a167=(a167/a161);
  a187=(a158*a016);
  a187=(a187/a161);
  a188=(a187/a161);
  a174=(a188*a174);
  a167=(a167-a174);
  a167=(a075*a167);
  a168=(a187*a168);
  a167=(a167+a168);
  a167=(a157*a167);
  a168=(a187*a075);
  a177=(a168*a177);
  a177=(a127?a177:0);
  a167=(a167+a177);
  a167=(a036*a167);
  a177=(a168*a157);
  a173=(a177*a173);
  a167=(a167+a173);
  a167=(a055*a167);
  a173=(a177*a036);
  a167=(a167+a173);
  a169=(a169+a167);
  if (res[0]!=0) res[0][14]=a169;
  a169=(2.*a050);
  a165=(a165*a169);
  a164=(a164*a165);
  a169=(a055*a164);
  a169=(a023*a169);
  a167=(a050*a164);
  a167=(a167+a016);
  a167=(a110*a167);
  a169=(a169-a167);
  a167=(a162*a169);
  a173=(a172*a169);
  a174=(a171*a173);
  a189=(a170*a174);
  a189=(a075*a189);
  a167=(a167-a189);
  a167=(a157*a167);
  a189=(a055*a164);
  a189=(a110*a189);
  a190=(a050*a164);
  a190=(a190+a016);
  a190=(a023*a190);
  a189=(a189+a190);
  a189=(a146*a189);
  a189=(a132*a189);
  a189=(a155*a189);
  a165=(a165/a180);
  a179=(a179*a165);
  a178=(a178*a179);
  a178=(a151*a178);
  a189=(a189+a178);
  a189=(a176*a189);
  a178=(a175*a189);
  a178=(a127?a178:0);
  a167=(a167+a178);
  a167=(a036*a167);
  a173=(a173/a043);
  a173=(a182*a173);
  a173=(a181*a173);
  a178=(a166*a173);
  a167=(a167+a178);
  a167=(a066*a167);
  if (res[0]!=0) res[0][15]=a167;
  a167=(a158*a164);
  a167=(a167/a161);
  a178=(a184*a174);
  a167=(a167-a178);
  a167=(a075*a167);
  a178=(a183*a169);
  a167=(a167+a178);
  a167=(a157*a167);
  a178=(a185*a189);
  a178=(a127?a178:0);
  a167=(a167+a178);
  a167=(a036*a167);
  a178=(a186*a173);
  a167=(a167+a178);
  a167=(a050*a167);
  a178=(a186*a036);
  a167=(a167+a178);
  a178=(a157*a164);
  a179=(a016*a189);
  a179=(a127?a179:0);
  a178=(a178+a179);
  a178=(a055*a178);
  a167=(a167-a178);
  a167=(-a167);
  if (res[0]!=0) res[0][16]=a167;
  a167=(a157*a164);
  a178=(a016*a189);
  a178=(a127?a178:0);
  a167=(a167+a178);
  a167=(a050*a167);
  a178=(a016*a157);
  a167=(a167+a178);
  a164=(a158*a164);
  a164=(a164/a161);
  a174=(a188*a174);
  a164=(a164-a174);
  a164=(a075*a164);
  a169=(a187*a169);
  a164=(a164+a169);
  a164=(a157*a164);
  a189=(a168*a189);
  a189=(a127?a189:0);
  a164=(a164+a189);
  a164=(a036*a164);
  a173=(a177*a173);
  a164=(a164+a173);
  a164=(a055*a164);
  a167=(a167+a164);
  if (res[0]!=0) res[0][17]=a167;
  a167=arg[3]? arg[3][26] : 0;
  a164=(a167*a065);
  a173=arg[3]? arg[3][27] : 0;
  a189=(a173*a072);
  a164=(a164-a189);
  a189=(a107*a173);
  a169=(a033*a167);
  a189=(a189+a169);
  a169=casadi_sq(a189);
  a174=arg[0]? arg[0][4] : 0;
  a178=casadi_sq(a174);
  a179=arg[0]? arg[0][5] : 0;
  a165=casadi_sq(a179);
  a178=(a178+a165);
  a165=casadi_fmax(a169,a178);
  a180=pow(a165,a109);
  a190=(a180*a179);
  a191=arg[0]? arg[0][10] : 0;
  a192=(a190*a191);
  a164=(a164+a192);
  a192=(a180*a174);
  a193=arg[0]? arg[0][11] : 0;
  a194=(a192*a193);
  a164=(a164-a194);
  a194=casadi_fabs(a164);
  a195=(a194-a092);
  a195=(a195/a043);
  a196=casadi_fmax(a064,a195);
  a197=casadi_fmin(a126,a196);
  a198=sqrt(a165);
  a199=(a173+a198);
  a199=(a199-a167);
  a200=(a064<a199);
  a201=(a167*a173);
  a202=(a167-a173);
  a201=(a201/a202);
  a203=sqrt(a201);
  a204=(a128*a203);
  a205=arg[3]? arg[3][29] : 0;
  a206=casadi_sq(a205);
  a206=(a126-a206);
  a207=arg[3]? arg[3][28] : 0;
  a206=(a206/a207);
  a208=arg[3]? arg[3][31] : 0;
  a209=casadi_sq(a208);
  a209=(a126-a209);
  a210=arg[3]? arg[3][30] : 0;
  a209=(a209/a210);
  a211=(a206+a209);
  a204=(a204/a211);
  a212=arg[4]? arg[4][1] : 0;
  a213=casadi_fmax(a212,a144);
  a140=(a140/a213);
  a214=(a180*a174);
  a215=(a214*a191);
  a216=(a180*a179);
  a217=(a216*a193);
  a215=(a215+a217);
  a217=(a140*a215);
  a217=(a126+a217);
  a218=(a204*a217);
  a219=casadi_fmax(a152,a199);
  a220=pow(a219,a154);
  a221=(a218*a220);
  a221=(a200?a221:0);
  a222=casadi_fmax(a064,a221);
  a223=casadi_fmax(a092,a056);
  a224=casadi_fmax(a223,a194);
  a225=(a158/a224);
  a226=pow(a165,a163);
  a226=(a109*a226);
  a227=(a169<=a178);
  a228=(a178<=a169);
  a228=(a228+a227);
  a227=(a227/a228);
  a228=(2.*a174);
  a228=(a227*a228);
  a229=(a226*a228);
  a230=(a174*a229);
  a230=(a230+a180);
  a230=(a193*a230);
  a231=(a179*a229);
  a231=(a191*a231);
  a230=(a230-a231);
  a231=(a225*a230);
  a232=(a173*a072);
  a233=(a167*a065);
  a232=(a232-a233);
  a233=(a180*a174);
  a234=(a233*a193);
  a232=(a232+a234);
  a234=(a180*a179);
  a235=(a234*a191);
  a232=(a232-a235);
  a235=(a225/a224);
  a236=(a223<=a194);
  a237=(a194<=a223);
  a237=(a237+a236);
  a236=(a236/a237);
  a237=casadi_sign(a164);
  a238=(a179*a229);
  a238=(a191*a238);
  a239=(a174*a229);
  a239=(a239+a180);
  a239=(a193*a239);
  a238=(a238-a239);
  a238=(a237*a238);
  a239=(a236*a238);
  a240=(a235*a239);
  a240=(a232*a240);
  a231=(a231-a240);
  a231=(a222*a231);
  a240=(a225*a232);
  a241=(a064<=a221);
  a242=(a221<=a064);
  a242=(a242+a241);
  a241=(a241/a242);
  a242=(a174*a229);
  a242=(a242+a180);
  a242=(a191*a242);
  a243=(a179*a229);
  a243=(a193*a243);
  a242=(a242+a243);
  a242=(a140*a242);
  a242=(a204*a242);
  a242=(a220*a242);
  a243=(a154-a126);
  a243=pow(a219,a243);
  a243=(a154*a243);
  a244=(a152<=a199);
  a245=(a199<=a152);
  a245=(a245+a244);
  a244=(a244/a245);
  a245=(2.*a198);
  a228=(a228/a245);
  a228=(a244*a228);
  a228=(a243*a228);
  a228=(a218*a228);
  a242=(a242+a228);
  a242=(a241*a242);
  a228=(a240*a242);
  a228=(a200?a228:0);
  a231=(a231+a228);
  a231=(a197*a231);
  a228=(a240*a222);
  a246=(a196<=a126);
  a247=(a126<=a196);
  a247=(a247+a246);
  a246=(a246/a247);
  a247=(a064<=a195);
  a248=(a195<=a064);
  a248=(a248+a247);
  a247=(a247/a248);
  a238=(a238/a043);
  a238=(a247*a238);
  a238=(a246*a238);
  a248=(a228*a238);
  a231=(a231+a248);
  a248=(a167*a231);
  a231=(a173*a231);
  a248=(a248-a231);
  a248=(-a248);
  if (res[0]!=0) res[0][18]=a248;
  if (res[0]!=0) res[0][19]=a231;
  a231=(a158*a229);
  a231=(a231/a224);
  a248=(a158*a180);
  a248=(a248/a224);
  a249=(a248/a224);
  a250=(a249*a239);
  a231=(a231-a250);
  a231=(a232*a231);
  a250=(a248*a230);
  a231=(a231+a250);
  a231=(a222*a231);
  a250=(a248*a232);
  a251=(a250*a242);
  a251=(a200?a251:0);
  a231=(a231+a251);
  a231=(a197*a231);
  a251=(a250*a222);
  a252=(a251*a238);
  a231=(a231+a252);
  a231=(a179*a231);
  a252=(a222*a229);
  a253=(a180*a242);
  a253=(a200?a253:0);
  a252=(a252+a253);
  a252=(a174*a252);
  a253=(a180*a222);
  a252=(a252+a253);
  a231=(a231-a252);
  a231=(-a231);
  if (res[0]!=0) res[0][20]=a231;
  a231=(a222*a229);
  a252=(a180*a242);
  a252=(a200?a252:0);
  a231=(a231+a252);
  a231=(a179*a231);
  a229=(a158*a229);
  a229=(a229/a224);
  a252=(a158*a180);
  a252=(a252/a224);
  a253=(a252/a224);
  a239=(a253*a239);
  a229=(a229-a239);
  a229=(a232*a229);
  a230=(a252*a230);
  a229=(a229+a230);
  a229=(a222*a229);
  a230=(a252*a232);
  a242=(a230*a242);
  a242=(a200?a242:0);
  a229=(a229+a242);
  a229=(a197*a229);
  a242=(a230*a222);
  a238=(a242*a238);
  a229=(a229+a238);
  a229=(a174*a229);
  a238=(a242*a197);
  a229=(a229+a238);
  a231=(a231+a229);
  if (res[0]!=0) res[0][21]=a231;
  a231=(2.*a179);
  a227=(a227*a231);
  a226=(a226*a227);
  a231=(a174*a226);
  a231=(a193*a231);
  a229=(a179*a226);
  a229=(a229+a180);
  a229=(a191*a229);
  a231=(a231-a229);
  a229=(a225*a231);
  a238=(a179*a226);
  a238=(a238+a180);
  a238=(a191*a238);
  a239=(a174*a226);
  a239=(a193*a239);
  a238=(a238-a239);
  a238=(a237*a238);
  a239=(a236*a238);
  a254=(a235*a239);
  a254=(a232*a254);
  a229=(a229-a254);
  a229=(a222*a229);
  a254=(a174*a226);
  a254=(a191*a254);
  a255=(a179*a226);
  a255=(a255+a180);
  a255=(a193*a255);
  a254=(a254+a255);
  a254=(a140*a254);
  a254=(a204*a254);
  a254=(a220*a254);
  a227=(a227/a245);
  a244=(a244*a227);
  a243=(a243*a244);
  a243=(a218*a243);
  a254=(a254+a243);
  a254=(a241*a254);
  a243=(a240*a254);
  a243=(a200?a243:0);
  a229=(a229+a243);
  a229=(a197*a229);
  a238=(a238/a043);
  a238=(a247*a238);
  a238=(a246*a238);
  a243=(a228*a238);
  a229=(a229+a243);
  a243=(a167*a229);
  a229=(a173*a229);
  a243=(a243-a229);
  a243=(-a243);
  if (res[0]!=0) res[0][22]=a243;
  if (res[0]!=0) res[0][23]=a229;
  a229=(a158*a226);
  a229=(a229/a224);
  a243=(a249*a239);
  a229=(a229-a243);
  a229=(a232*a229);
  a243=(a248*a231);
  a229=(a229+a243);
  a229=(a222*a229);
  a243=(a250*a254);
  a243=(a200?a243:0);
  a229=(a229+a243);
  a229=(a197*a229);
  a243=(a251*a238);
  a229=(a229+a243);
  a229=(a179*a229);
  a243=(a251*a197);
  a229=(a229+a243);
  a243=(a222*a226);
  a244=(a180*a254);
  a244=(a200?a244:0);
  a243=(a243+a244);
  a243=(a174*a243);
  a229=(a229-a243);
  a229=(-a229);
  if (res[0]!=0) res[0][24]=a229;
  a229=(a222*a226);
  a243=(a180*a254);
  a243=(a200?a243:0);
  a229=(a229+a243);
  a229=(a179*a229);
  a243=(a180*a222);
  a229=(a229+a243);
  a226=(a158*a226);
  a226=(a226/a224);
  a239=(a253*a239);
  a226=(a226-a239);
  a226=(a232*a226);
  a231=(a252*a231);
  a226=(a226+a231);
  a226=(a222*a226);
  a254=(a230*a254);
  a254=(a200?a254:0);
  a226=(a226+a254);
  a226=(a197*a226);
  a238=(a242*a238);
  a226=(a226+a238);
  a226=(a174*a226);
  a229=(a229+a226);
  if (res[0]!=0) res[0][25]=a229;
  a229=(a173-a167);
  a226=(a225*a229);
  a238=(a167-a173);
  a238=(a237*a238);
  a254=(a236*a238);
  a231=(a235*a254);
  a231=(a232*a231);
  a226=(a226-a231);
  a226=(a222*a226);
  a226=(a197*a226);
  a238=(a238/a043);
  a238=(a247*a238);
  a238=(a246*a238);
  a231=(a228*a238);
  a226=(a226+a231);
  a231=(a167*a226);
  a239=(a162*a066);
  a243=(a172*a066);
  a244=(a171*a243);
  a227=(a170*a244);
  a227=(a075*a227);
  a239=(a239-a227);
  a239=(a157*a239);
  a239=(a036*a239);
  a243=(a243/a043);
  a243=(a182*a243);
  a243=(a181*a243);
  a227=(a166*a243);
  a239=(a239+a227);
  a239=(a066*a239);
  a226=(a173*a226);
  a239=(a239+a226);
  a231=(a231-a239);
  a239=(2.*a065);
  a227=(a002*a239);
  a227=(a006*a227);
  a245=(2.*a072);
  a255=(a008*a245);
  a255=(a011*a255);
  a255=(a227+a255);
  a256=(a067*a255);
  a231=(a231+a256);
  a256=(a002*a239);
  a256=(a019*a256);
  a257=(a008*a245);
  a257=(a021*a257);
  a257=(a256+a257);
  a258=(a090*a257);
  a231=(a231-a258);
  a258=(a029*a245);
  a258=(a011*a258);
  a259=(a227+a258);
  a260=(a032*a245);
  a260=(a010*a260);
  a259=(a259+a260);
  a260=(a017*a259);
  a231=(a231+a260);
  a260=(a029*a245);
  a260=(a021*a260);
  a261=(a256+a260);
  a262=(a032*a245);
  a262=(a041*a262);
  a261=(a261+a262);
  a262=(a102*a261);
  a231=(a231-a262);
  a227=(a227+a258);
  a258=(a048*a245);
  a258=(a010*a258);
  a227=(a227+a258);
  a258=(a035*a227);
  a231=(a231+a258);
  a256=(a256+a260);
  a260=(a048*a245);
  a260=(a041*a260);
  a256=(a256+a260);
  a260=(a105*a256);
  a231=(a231-a260);
  a231=(-a231);
  if (res[0]!=0) res[0][26]=a231;
  a231=(a112*a259);
  a231=(a231-a226);
  a226=(a115*a261);
  a231=(a231-a226);
  a226=(a037*a227);
  a231=(a231+a226);
  a226=(a118*a256);
  a231=(a231-a226);
  a226=(a119*a257);
  a226=(a011*a226);
  a231=(a231-a226);
  a226=(a123*a255);
  a226=(a021*a226);
  a231=(a231+a226);
  a231=(-a231);
  if (res[0]!=0) res[0][27]=a231;
  a231=(a183*a066);
  a226=(a184*a244);
  a226=(a075*a226);
  a231=(a231-a226);
  a231=(a157*a231);
  a231=(a036*a231);
  a226=(a186*a243);
  a231=(a231+a226);
  a231=(a050*a231);
  a257=(a001*a257);
  a231=(a231+a257);
  a261=(a028*a261);
  a231=(a231+a261);
  a256=(a038*a256);
  a231=(a231+a256);
  a113=(a113*a239);
  a113=(a019*a113);
  a231=(a231+a113);
  a231=(-a231);
  if (res[0]!=0) res[0][28]=a231;
  a255=(a001*a255);
  a231=(a187*a066);
  a244=(a188*a244);
  a244=(a075*a244);
  a231=(a231-a244);
  a231=(a157*a231);
  a231=(a036*a231);
  a243=(a177*a243);
  a231=(a231+a243);
  a231=(a055*a231);
  a231=(a255-a231);
  a259=(a028*a259);
  a231=(a231+a259);
  a227=(a038*a227);
  a231=(a231+a227);
  a049=(a049*a239);
  a049=(a006*a049);
  a231=(a231+a049);
  a231=(-a231);
  if (res[0]!=0) res[0][29]=a231;
  a231=(a248*a229);
  a049=(a249*a254);
  a049=(a232*a049);
  a231=(a231-a049);
  a231=(a222*a231);
  a231=(a197*a231);
  a049=(a251*a238);
  a231=(a231+a049);
  a231=(a179*a231);
  a231=(a231+a257);
  a231=(a231+a261);
  a231=(a231+a256);
  a231=(-a231);
  if (res[0]!=0) res[0][30]=a231;
  a229=(a252*a229);
  a254=(a253*a254);
  a254=(a232*a254);
  a229=(a229-a254);
  a229=(a222*a229);
  a229=(a197*a229);
  a238=(a242*a238);
  a229=(a229+a238);
  a229=(a174*a229);
  a255=(a255-a229);
  a255=(a255+a259);
  a255=(a255+a227);
  a255=(-a255);
  if (res[0]!=0) res[0][31]=a255;
  a255=(a237*a173);
  a227=(a236*a255);
  a259=(a235*a227);
  a259=(a232*a259);
  a229=(a225*a173);
  a259=(a259+a229);
  a259=(a222*a259);
  a259=(a197*a259);
  a255=(a255/a043);
  a255=(a247*a255);
  a255=(a246*a255);
  a229=(a228*a255);
  a259=(a259-a229);
  a229=(a167*a259);
  a259=(a173*a259);
  a229=(a229-a259);
  a238=(a008*a245);
  a238=(a011*a238);
  a254=(a067*a238);
  a229=(a229+a254);
  a254=(a008*a245);
  a254=(a021*a254);
  a231=(a090*a254);
  a229=(a229-a231);
  a231=(a029*a245);
  a231=(a011*a231);
  a256=(a032*a245);
  a256=(a010*a256);
  a256=(a231+a256);
  a261=(a017*a256);
  a229=(a229+a261);
  a261=(a029*a245);
  a261=(a021*a261);
  a257=(a032*a245);
  a257=(a041*a257);
  a257=(a261+a257);
  a049=(a102*a257);
  a229=(a229-a049);
  a049=(a048*a245);
  a049=(a010*a049);
  a231=(a231+a049);
  a049=(a035*a231);
  a229=(a229+a049);
  a245=(a048*a245);
  a245=(a041*a245);
  a261=(a261+a245);
  a245=(a105*a261);
  a229=(a229-a245);
  a229=(-a229);
  if (res[0]!=0) res[0][32]=a229;
  a229=(a112*a256);
  a229=(a229-a259);
  a259=(a115*a257);
  a229=(a229-a259);
  a259=(a037*a231);
  a229=(a229+a259);
  a259=(a118*a261);
  a229=(a229-a259);
  a259=(a119*a254);
  a259=(a011*a259);
  a229=(a229-a259);
  a259=(a123*a238);
  a259=(a021*a259);
  a229=(a229+a259);
  a229=(-a229);
  if (res[0]!=0) res[0][33]=a229;
  a254=(a001*a254);
  a257=(a028*a257);
  a229=(a254+a257);
  a261=(a038*a261);
  a229=(a229+a261);
  a229=(-a229);
  if (res[0]!=0) res[0][34]=a229;
  a238=(a001*a238);
  a256=(a028*a256);
  a229=(a238+a256);
  a231=(a038*a231);
  a229=(a229+a231);
  a229=(-a229);
  if (res[0]!=0) res[0][35]=a229;
  a229=(a249*a227);
  a229=(a232*a229);
  a259=(a248*a173);
  a229=(a229+a259);
  a229=(a222*a229);
  a229=(a197*a229);
  a259=(a251*a255);
  a229=(a229-a259);
  a229=(a179*a229);
  a229=(a229+a254);
  a229=(a229+a257);
  a229=(a229+a261);
  a229=(-a229);
  if (res[0]!=0) res[0][36]=a229;
  a227=(a253*a227);
  a227=(a232*a227);
  a229=(a252*a173);
  a227=(a227+a229);
  a227=(a222*a227);
  a227=(a197*a227);
  a255=(a242*a255);
  a227=(a227-a255);
  a227=(a174*a227);
  a238=(a238-a227);
  a238=(a238+a256);
  a238=(a238+a231);
  a238=(-a238);
  if (res[0]!=0) res[0][37]=a238;
  a238=(a172*a071);
  a231=(a171*a238);
  a256=(a170*a231);
  a256=(a075*a256);
  a227=(a162*a071);
  a256=(a256-a227);
  a256=(a157*a256);
  a147=(a146*a147);
  a147=(a132*a147);
  a147=(a155*a147);
  a147=(a176*a147);
  a227=(a175*a147);
  a227=(a127?a227:0);
  a256=(a256+a227);
  a256=(a036*a256);
  a238=(a238/a043);
  a238=(a182*a238);
  a238=(a181*a238);
  a227=(a166*a238);
  a256=(a256-a227);
  a256=(a066*a256);
  if (res[0]!=0) res[0][38]=a256;
  a256=(a184*a231);
  a256=(a075*a256);
  a227=(a183*a071);
  a256=(a256-a227);
  a256=(a157*a256);
  a227=(a185*a147);
  a227=(a127?a227:0);
  a256=(a256+a227);
  a256=(a036*a256);
  a227=(a186*a238);
  a256=(a256-a227);
  a256=(a050*a256);
  a227=(a016*a147);
  a227=(a055*a227);
  a227=(-a227);
  a227=(a127?a227:0);
  a256=(a256+a227);
  a256=(-a256);
  if (res[0]!=0) res[0][39]=a256;
  a256=(a016*a147);
  a256=(a050*a256);
  a256=(a127?a256:0);
  a231=(a188*a231);
  a231=(a075*a231);
  a071=(a187*a071);
  a231=(a231-a071);
  a231=(a157*a231);
  a147=(a168*a147);
  a147=(a127?a147:0);
  a231=(a231+a147);
  a231=(a036*a231);
  a238=(a177*a238);
  a231=(a231-a238);
  a231=(a055*a231);
  a256=(a256+a231);
  if (res[0]!=0) res[0][40]=a256;
  a256=(a162*a026);
  a172=(a172*a026);
  a171=(a171*a172);
  a170=(a170*a171);
  a170=(a075*a170);
  a256=(a256-a170);
  a256=(a157*a256);
  a149=(a146*a149);
  a149=(a132*a149);
  a149=(a155*a149);
  a176=(a176*a149);
  a149=(a175*a176);
  a149=(a127?a149:0);
  a256=(a256+a149);
  a256=(a036*a256);
  a172=(a172/a043);
  a182=(a182*a172);
  a181=(a181*a182);
  a182=(a166*a181);
  a256=(a256+a182);
  a256=(a066*a256);
  if (res[0]!=0) res[0][41]=a256;
  a256=(a183*a026);
  a184=(a184*a171);
  a184=(a075*a184);
  a256=(a256-a184);
  a256=(a157*a256);
  a184=(a185*a176);
  a184=(a127?a184:0);
  a256=(a256+a184);
  a256=(a036*a256);
  a184=(a186*a181);
  a256=(a256+a184);
  a256=(a050*a256);
  a184=(a016*a176);
  a184=(a055*a184);
  a184=(-a184);
  a184=(a127?a184:0);
  a256=(a256+a184);
  a256=(-a256);
  if (res[0]!=0) res[0][42]=a256;
  a256=(a016*a176);
  a256=(a050*a256);
  a256=(a127?a256:0);
  a026=(a187*a026);
  a188=(a188*a171);
  a188=(a075*a188);
  a026=(a026-a188);
  a026=(a157*a026);
  a176=(a168*a176);
  a176=(a127?a176:0);
  a026=(a026+a176);
  a026=(a036*a026);
  a181=(a177*a181);
  a026=(a026+a181);
  a026=(a055*a026);
  a256=(a256+a026);
  if (res[0]!=0) res[0][43]=a256;
  a214=(a140*a214);
  a214=(a204*a214);
  a214=(a220*a214);
  a214=(a241*a214);
  a256=(a240*a214);
  a256=(a200?a256:0);
  a190=(a237*a190);
  a026=(a236*a190);
  a181=(a235*a026);
  a181=(a232*a181);
  a176=(a225*a234);
  a181=(a181+a176);
  a181=(a222*a181);
  a256=(a256-a181);
  a256=(a197*a256);
  a190=(a190/a043);
  a190=(a247*a190);
  a190=(a246*a190);
  a181=(a228*a190);
  a256=(a256+a181);
  a181=(a167*a256);
  a256=(a173*a256);
  a181=(a181-a256);
  a181=(-a181);
  if (res[0]!=0) res[0][44]=a181;
  if (res[0]!=0) res[0][45]=a256;
  a256=(a250*a214);
  a256=(a200?a256:0);
  a181=(a249*a026);
  a181=(a232*a181);
  a176=(a248*a234);
  a181=(a181+a176);
  a181=(a222*a181);
  a256=(a256-a181);
  a256=(a197*a256);
  a181=(a251*a190);
  a256=(a256+a181);
  a256=(a179*a256);
  a181=(a180*a214);
  a181=(a174*a181);
  a181=(-a181);
  a181=(a200?a181:0);
  a256=(a256+a181);
  a256=(-a256);
  if (res[0]!=0) res[0][46]=a256;
  a256=(a180*a214);
  a256=(a179*a256);
  a256=(a200?a256:0);
  a214=(a230*a214);
  a214=(a200?a214:0);
  a026=(a253*a026);
  a026=(a232*a026);
  a234=(a252*a234);
  a026=(a026+a234);
  a026=(a222*a026);
  a214=(a214-a026);
  a214=(a197*a214);
  a190=(a242*a190);
  a214=(a214+a190);
  a214=(a174*a214);
  a256=(a256+a214);
  if (res[0]!=0) res[0][47]=a256;
  a237=(a237*a192);
  a236=(a236*a237);
  a235=(a235*a236);
  a235=(a232*a235);
  a192=(a225*a233);
  a235=(a235+a192);
  a235=(a222*a235);
  a216=(a140*a216);
  a216=(a204*a216);
  a216=(a220*a216);
  a241=(a241*a216);
  a216=(a240*a241);
  a216=(a200?a216:0);
  a235=(a235+a216);
  a235=(a197*a235);
  a237=(a237/a043);
  a247=(a247*a237);
  a246=(a246*a247);
  a247=(a228*a246);
  a235=(a235-a247);
  a247=(a167*a235);
  a235=(a173*a235);
  a247=(a247-a235);
  a247=(-a247);
  if (res[0]!=0) res[0][48]=a247;
  if (res[0]!=0) res[0][49]=a235;
  a249=(a249*a236);
  a249=(a232*a249);
  a235=(a248*a233);
  a249=(a249+a235);
  a249=(a222*a249);
  a235=(a250*a241);
  a235=(a200?a235:0);
  a249=(a249+a235);
  a249=(a197*a249);
  a235=(a251*a246);
  a249=(a249-a235);
  a249=(a179*a249);
  a235=(a180*a241);
  a235=(a174*a235);
  a235=(-a235);
  a235=(a200?a235:0);
  a249=(a249+a235);
  a249=(-a249);
  if (res[0]!=0) res[0][50]=a249;
  a249=(a180*a241);
  a249=(a179*a249);
  a249=(a200?a249:0);
  a253=(a253*a236);
  a253=(a232*a253);
  a233=(a252*a233);
  a253=(a253+a233);
  a253=(a222*a253);
  a241=(a230*a241);
  a241=(a200?a241:0);
  a253=(a253+a241);
  a253=(a197*a253);
  a246=(a242*a246);
  a253=(a253-a246);
  a253=(a174*a253);
  a249=(a249+a253);
  if (res[0]!=0) res[0][51]=a249;
  a249=-1.;
  if (res[1]!=0) res[1][0]=a249;
  if (res[1]!=0) res[1][1]=a249;
  a249=(a105+a102);
  a249=(a249+a090);
  a253=(a019*a249);
  a253=(a053*a253);
  a246=(a035+a017);
  a246=(a246+a067);
  a241=(a006*a246);
  a241=(a053*a241);
  a253=(a253-a241);
  a241=(a038*a087);
  a241=(a241+a083);
  a083=(a069+a051);
  a233=(a038*a083);
  a241=(a241-a233);
  a233=(a038*a052);
  a236=(a030*a233);
  a241=(a241+a236);
  a236=(2.*a007);
  a235=(a038*a000);
  a236=(a236*a235);
  a241=(a241+a236);
  a236=(a028*a100);
  a236=(a236+a082);
  a082=(a069+a051);
  a247=(a028*a082);
  a236=(a236-a247);
  a247=(a028*a052);
  a237=(a004*a247);
  a236=(a236+a237);
  a237=(2.*a031);
  a216=(a028*a000);
  a237=(a237*a216);
  a236=(a236+a237);
  a237=(a241+a236);
  a192=(a001*a089);
  a192=(a192+a080);
  a080=(a069+a051);
  a256=(a001*a080);
  a192=(a192-a256);
  a256=(a001*a052);
  a214=(a011*a256);
  a190=(a008*a214);
  a192=(a192+a190);
  a190=(2.*a012);
  a026=(a001*a000);
  a190=(a190*a026);
  a192=(a192+a190);
  a237=(a237+a192);
  a190=(a006*a237);
  a253=(a253+a190);
  a190=(a058+a063);
  a234=(a038*a190);
  a181=(a038*a077);
  a181=(a181+a086);
  a234=(a234-a181);
  a181=(a039*a233);
  a234=(a234+a181);
  a181=(2.*a020);
  a181=(a181*a235);
  a234=(a234+a181);
  a181=(a058+a063);
  a235=(a028*a181);
  a086=(a028*a099);
  a086=(a086+a027);
  a235=(a235-a086);
  a086=(a042*a247);
  a235=(a235+a086);
  a086=(2.*a040);
  a086=(a086*a216);
  a235=(a235+a086);
  a086=(a234+a235);
  a216=(a058+a063);
  a027=(a001*a216);
  a176=(a001*a078);
  a176=(a176+a085);
  a027=(a027-a176);
  a176=(a021*a256);
  a085=(a008*a176);
  a027=(a027+a085);
  a085=(2.*a022);
  a085=(a085*a026);
  a027=(a027+a085);
  a086=(a086+a027);
  a085=(a019*a086);
  a253=(a253+a085);
  if (res[2]!=0) res[2][0]=a253;
  a253=(a118+a115);
  a119=(a119*a011);
  a253=(a253+a119);
  a085=(a019*a253);
  a085=(a053*a085);
  a026=(a037+a112);
  a123=(a123*a021);
  a026=(a026+a123);
  a188=(a006*a026);
  a188=(a053*a188);
  a085=(a085-a188);
  a188=(a038*a000);
  a171=(a030*a188);
  a184=(a028*a000);
  a182=(a004*a184);
  a172=(a171+a182);
  a149=(a001*a000);
  a170=(a011*a149);
  a231=(a008*a170);
  a172=(a172+a231);
  a238=(a006*a172);
  a085=(a085+a238);
  a238=(a039*a188);
  a147=(a042*a184);
  a071=(a238+a147);
  a227=(a021*a149);
  a255=(a008*a227);
  a071=(a071+a255);
  a229=(a019*a071);
  a085=(a085+a229);
  if (res[2]!=0) res[2][1]=a085;
  a085=(a038+a028);
  a085=(a085+a001);
  a229=(a019*a085);
  a229=(a053*a229);
  a261=(a038*a000);
  a257=(a028*a000);
  a254=(a261+a257);
  a259=(a001*a000);
  a254=(a254+a259);
  a245=(a006*a254);
  a229=(a229+a245);
  a229=(-a229);
  if (res[2]!=0) res[2][2]=a229;
  a229=(a038*a000);
  a245=(a028*a000);
  a049=(a229+a245);
  a239=(a001*a000);
  a049=(a049+a239);
  a243=(a019*a049);
  a244=(a038+a028);
  a244=(a244+a001);
  a113=(a006*a244);
  a113=(a053*a113);
  a243=(a243-a113);
  if (res[2]!=0) res[2][3]=a243;
  a243=(a038+a028);
  a243=(a243+a001);
  a113=(a019*a243);
  a113=(a053*a113);
  a226=(a038*a000);
  a260=(a028*a000);
  a258=(a226+a260);
  a262=(a001*a000);
  a258=(a258+a262);
  a263=(a006*a258);
  a113=(a113+a263);
  a113=(-a113);
  if (res[2]!=0) res[2][4]=a113;
  a113=(a038*a000);
  a263=(a028*a000);
  a264=(a113+a263);
  a265=(a001*a000);
  a264=(a264+a265);
  a266=(a019*a264);
  a267=(a038+a028);
  a267=(a267+a001);
  a268=(a006*a267);
  a268=(a053*a268);
  a266=(a266-a268);
  if (res[2]!=0) res[2][5]=a266;
  a025=(a025*a006);
  a015=(a015*a019);
  a025=(a025-a015);
  a015=(a019*a063);
  a266=(a060*a015);
  a025=(a025+a266);
  a266=(a006*a051);
  a268=(a060*a266);
  a025=(a025-a268);
  a268=casadi_sq(a060);
  a268=(a268*a000);
  a025=(a025+a268);
  if (res[2]!=0) res[2][6]=a025;
  a025=(a053*a019);
  a268=(a060*a025);
  a268=(a268+a079);
  a268=(a051-a268);
  a269=(a006*a000);
  a270=(a060*a269);
  a268=(a268-a270);
  if (res[2]!=0) res[2][7]=a268;
  a053=(a053*a006);
  a268=(a060*a053);
  a268=(a268+a084);
  a268=(a063-a268);
  a270=(a019*a000);
  a271=(a060*a270);
  a268=(a268+a271);
  if (res[2]!=0) res[2][8]=a268;
  if (res[2]!=0) res[2][9]=a000;
  a006=(a061*a006);
  a268=(a079*a006);
  a019=(a061*a019);
  a271=(a084*a019);
  a268=(a268-a271);
  a015=(a061*a015);
  a268=(a268+a015);
  a266=(a061*a266);
  a268=(a268-a266);
  a266=(2.*a060);
  a015=(a061*a000);
  a266=(a266*a015);
  a268=(a268+a266);
  if (res[2]!=0) res[2][10]=a268;
  a025=(a061*a025);
  a269=(a061*a269);
  a025=(a025+a269);
  a025=(-a025);
  if (res[2]!=0) res[2][11]=a025;
  a270=(a061*a270);
  a053=(a061*a053);
  a270=(a270-a053);
  if (res[2]!=0) res[2][12]=a270;
  a270=(a105+a102);
  a053=(a021*a270);
  a053=(a073*a053);
  a025=(a035+a017);
  a269=(a011*a025);
  a269=(a073*a269);
  a053=(a053-a269);
  a269=(a007*a233);
  a268=(a031*a247);
  a266=(a269+a268);
  a266=(a266+a241);
  a266=(a266+a236);
  a015=(a011*a266);
  a053=(a053+a015);
  a233=(a020*a233);
  a247=(a040*a247);
  a015=(a233+a247);
  a015=(a015+a234);
  a015=(a015+a235);
  a271=(a021*a015);
  a053=(a053+a271);
  if (res[2]!=0) res[2][13]=a053;
  a053=(a118+a115);
  a271=(a021*a053);
  a271=(a073*a271);
  a272=(a037+a112);
  a273=(a011*a272);
  a273=(a073*a273);
  a271=(a271-a273);
  a273=(a038*a087);
  a273=(a273+a116);
  a116=(a069+a051);
  a274=(a038*a116);
  a273=(a273-a274);
  a274=(2.*a030);
  a275=(a038*a052);
  a274=(a274*a275);
  a273=(a273+a274);
  a274=(a007*a188);
  a273=(a273+a274);
  a274=(a028*a100);
  a274=(a274+a114);
  a114=(a028*a116);
  a274=(a274-a114);
  a114=(2.*a004);
  a276=(a028*a052);
  a114=(a114*a276);
  a274=(a274+a114);
  a114=(a031*a184);
  a274=(a274+a114);
  a114=(a273+a274);
  a114=(a114+a171);
  a114=(a114+a182);
  a277=(a011*a114);
  a271=(a271+a277);
  a277=(a058+a063);
  a278=(a038*a277);
  a279=(a038*a077);
  a279=(a279+a047);
  a278=(a278-a279);
  a279=(2.*a039);
  a279=(a279*a275);
  a278=(a278+a279);
  a188=(a020*a188);
  a278=(a278+a188);
  a188=(a028*a277);
  a279=(a028*a099);
  a279=(a279+a117);
  a188=(a188-a279);
  a279=(2.*a042);
  a279=(a279*a276);
  a188=(a188+a279);
  a184=(a040*a184);
  a188=(a188+a184);
  a184=(a278+a188);
  a184=(a184+a238);
  a184=(a184+a147);
  a279=(a021*a184);
  a271=(a271+a279);
  if (res[2]!=0) res[2][14]=a271;
  a271=(a038+a028);
  a279=(a021*a271);
  a279=(a073*a279);
  a276=(a038*a052);
  a117=(a028*a052);
  a275=(a276+a117);
  a275=(a275+a261);
  a275=(a275+a257);
  a047=(a011*a275);
  a279=(a279+a047);
  a279=(-a279);
  if (res[2]!=0) res[2][15]=a279;
  a279=(a038*a052);
  a047=(a028*a052);
  a280=(a279+a047);
  a280=(a280+a229);
  a280=(a280+a245);
  a281=(a021*a280);
  a282=(a038+a028);
  a283=(a011*a282);
  a283=(a073*a283);
  a281=(a281-a283);
  if (res[2]!=0) res[2][16]=a281;
  a281=(a038+a028);
  a283=(a021*a281);
  a283=(a073*a283);
  a284=(a038*a052);
  a285=(a028*a052);
  a286=(a284+a285);
  a286=(a286+a226);
  a286=(a286+a260);
  a287=(a011*a286);
  a283=(a283+a287);
  a283=(-a283);
  if (res[2]!=0) res[2][17]=a283;
  a283=(a038*a052);
  a287=(a028*a052);
  a288=(a283+a287);
  a288=(a288+a113);
  a288=(a288+a263);
  a289=(a021*a288);
  a290=(a038+a028);
  a291=(a011*a290);
  a291=(a073*a291);
  a289=(a289-a291);
  if (res[2]!=0) res[2][18]=a289;
  a289=(a012*a089);
  a291=(a022*a078);
  a289=(a289-a291);
  a291=(a084*a022);
  a289=(a289-a291);
  a291=(a079*a012);
  a289=(a289+a291);
  a216=(a022*a216);
  a289=(a289+a216);
  a080=(a012*a080);
  a289=(a289-a080);
  a080=(a059*a021);
  a216=(a057*a011);
  a080=(a080+a216);
  a216=(a080*a052);
  a289=(a289+a216);
  a216=casadi_sq(a022);
  a291=casadi_sq(a012);
  a216=(a216+a291);
  a216=(a216*a000);
  a289=(a289+a216);
  if (res[2]!=0) res[2][19]=a289;
  a121=(a121*a011);
  a289=(a078*a021);
  a216=(a008*a289);
  a121=(a121-a216);
  a216=(a089*a011);
  a291=(a008*a216);
  a121=(a121+a291);
  a034=(a034*a021);
  a121=(a121-a034);
  a034=(a021*a277);
  a291=(a008*a034);
  a121=(a121+a291);
  a291=(a011*a116);
  a292=(a008*a291);
  a121=(a121-a292);
  a292=casadi_sq(a008);
  a292=(a292*a052);
  a121=(a121+a292);
  a080=(a080*a000);
  a121=(a121+a080);
  if (res[2]!=0) res[2][20]=a121;
  a121=(a089+a079);
  a121=(a069-a121);
  a121=(a121+a051);
  a080=(a011*a052);
  a292=(a008*a080);
  a121=(a121-a292);
  a292=(a012*a000);
  a121=(a121-a292);
  if (res[2]!=0) res[2][21]=a121;
  a121=(a078+a084);
  a121=(a058-a121);
  a121=(a121+a063);
  a292=(a021*a052);
  a293=(a008*a292);
  a121=(a121+a293);
  a293=(a022*a000);
  a121=(a121+a293);
  if (res[2]!=0) res[2][22]=a121;
  a121=(a069+a051);
  a089=(a089+a079);
  a089=(a121-a089);
  a293=(a011*a052);
  a294=(a008*a293);
  a089=(a089-a294);
  a294=(a012*a000);
  a089=(a089-a294);
  if (res[2]!=0) res[2][23]=a089;
  a089=(a058+a063);
  a078=(a078+a084);
  a078=(a089-a078);
  a294=(a021*a052);
  a295=(a008*a294);
  a078=(a078+a295);
  a295=(a022*a000);
  a078=(a078+a295);
  if (res[2]!=0) res[2][24]=a078;
  a078=(a052+a000);
  if (res[2]!=0) res[2][25]=a078;
  a078=(a052+a000);
  if (res[2]!=0) res[2][26]=a078;
  a078=(a021*a090);
  a078=(a073*a078);
  a295=(a011*a067);
  a295=(a073*a295);
  a078=(a078-a295);
  a214=(a012*a214);
  a078=(a078+a214);
  a176=(a022*a176);
  a078=(a078+a176);
  a176=(a011*a192);
  a078=(a078+a176);
  a176=(a021*a027);
  a078=(a078+a176);
  if (res[2]!=0) res[2][27]=a078;
  a078=(a001*a011);
  a176=(a079*a078);
  a289=(a001*a289);
  a176=(a176-a289);
  a216=(a001*a216);
  a176=(a176+a216);
  a216=(a001*a021);
  a289=(a084*a216);
  a176=(a176-a289);
  a034=(a001*a034);
  a176=(a176+a034);
  a291=(a001*a291);
  a176=(a176-a291);
  a291=(2.*a008);
  a034=(a001*a052);
  a291=(a291*a034);
  a176=(a176+a291);
  a291=(a021*a119);
  a291=(a073*a291);
  a176=(a176+a291);
  a291=(a011*a123);
  a291=(a073*a291);
  a176=(a176-a291);
  a170=(a012*a170);
  a176=(a176+a170);
  a227=(a022*a227);
  a176=(a176+a227);
  a227=(a011*a231);
  a176=(a176+a227);
  a227=(a021*a255);
  a176=(a176+a227);
  if (res[2]!=0) res[2][28]=a176;
  a080=(a001*a080);
  a176=(a021*a001);
  a176=(a073*a176);
  a080=(a080+a176);
  a176=(a011*a259);
  a080=(a080+a176);
  a080=(-a080);
  if (res[2]!=0) res[2][29]=a080;
  a292=(a001*a292);
  a080=(a011*a001);
  a080=(a073*a080);
  a292=(a292-a080);
  a080=(a021*a239);
  a292=(a292+a080);
  if (res[2]!=0) res[2][30]=a292;
  a293=(a001*a293);
  a292=(a021*a001);
  a292=(a073*a292);
  a293=(a293+a292);
  a292=(a011*a262);
  a293=(a293+a292);
  a293=(-a293);
  if (res[2]!=0) res[2][31]=a293;
  a294=(a001*a294);
  a011=(a011*a001);
  a011=(a073*a011);
  a294=(a294-a011);
  a021=(a021*a265);
  a294=(a294+a021);
  if (res[2]!=0) res[2][32]=a294;
  a294=(a041*a105);
  a294=(a073*a294);
  a021=(a010*a035);
  a021=(a073*a021);
  a294=(a294-a021);
  a269=(a269+a241);
  a241=(a010*a269);
  a294=(a294+a241);
  a233=(a233+a234);
  a234=(a041*a233);
  a294=(a294+a234);
  if (res[2]!=0) res[2][33]=a294;
  a294=(a041*a118);
  a294=(a073*a294);
  a234=(a010*a037);
  a234=(a073*a234);
  a294=(a294-a234);
  a273=(a273+a171);
  a171=(a010*a273);
  a294=(a294+a171);
  a278=(a278+a238);
  a238=(a041*a278);
  a294=(a294+a238);
  if (res[2]!=0) res[2][34]=a294;
  a294=(a041*a038);
  a294=(a073*a294);
  a276=(a276+a261);
  a261=(a010*a276);
  a294=(a294+a261);
  a294=(-a294);
  if (res[2]!=0) res[2][35]=a294;
  a279=(a279+a229);
  a229=(a041*a279);
  a294=(a010*a038);
  a294=(a073*a294);
  a229=(a229-a294);
  if (res[2]!=0) res[2][36]=a229;
  a229=(a041*a038);
  a229=(a073*a229);
  a284=(a284+a226);
  a226=(a010*a284);
  a229=(a229+a226);
  a229=(-a229);
  if (res[2]!=0) res[2][37]=a229;
  a283=(a283+a113);
  a113=(a041*a283);
  a229=(a010*a038);
  a229=(a073*a229);
  a113=(a113-a229);
  if (res[2]!=0) res[2][38]=a113;
  a113=(a031*a100);
  a229=(a040*a099);
  a113=(a113-a229);
  a229=(a084*a040);
  a113=(a113-a229);
  a229=(a079*a031);
  a113=(a113+a229);
  a181=(a040*a181);
  a113=(a113+a181);
  a082=(a031*a082);
  a113=(a113-a082);
  a082=(a042*a040);
  a181=(a004*a031);
  a082=(a082+a181);
  a181=(a082*a052);
  a113=(a113+a181);
  a181=casadi_sq(a040);
  a229=casadi_sq(a031);
  a181=(a181+a229);
  a181=(a181*a000);
  a113=(a113+a181);
  if (res[2]!=0) res[2][39]=a113;
  a113=(a004*a100);
  a181=(a042*a099);
  a113=(a113-a181);
  a181=(a084*a042);
  a113=(a113-a181);
  a181=(a079*a004);
  a113=(a113+a181);
  a181=(a042*a277);
  a113=(a113+a181);
  a181=(a004*a116);
  a113=(a113-a181);
  a181=casadi_sq(a042);
  a229=casadi_sq(a004);
  a181=(a181+a229);
  a181=(a181*a052);
  a113=(a113+a181);
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
  a268=(a268+a236);
  a236=(a010*a268);
  a099=(a099+a236);
  a247=(a247+a235);
  a235=(a041*a247);
  a099=(a099+a235);
  if (res[2]!=0) res[2][47]=a099;
  a099=(a041*a115);
  a099=(a073*a099);
  a235=(a010*a112);
  a235=(a073*a235);
  a099=(a099-a235);
  a274=(a274+a182);
  a182=(a010*a274);
  a099=(a099+a182);
  a188=(a188+a147);
  a147=(a041*a188);
  a099=(a099+a147);
  if (res[2]!=0) res[2][48]=a099;
  a099=(a041*a028);
  a099=(a073*a099);
  a117=(a117+a257);
  a257=(a010*a117);
  a099=(a099+a257);
  a099=(-a099);
  if (res[2]!=0) res[2][49]=a099;
  a047=(a047+a245);
  a245=(a041*a047);
  a099=(a010*a028);
  a099=(a073*a099);
  a245=(a245-a099);
  if (res[2]!=0) res[2][50]=a245;
  a245=(a041*a028);
  a245=(a073*a245);
  a285=(a285+a260);
  a260=(a010*a285);
  a245=(a245+a260);
  a245=(-a245);
  if (res[2]!=0) res[2][51]=a245;
  a287=(a287+a263);
  a041=(a041*a287);
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
  a190=(a020*a190);
  a041=(a041+a190);
  a083=(a007*a083);
  a041=(a041-a083);
  a083=(a039*a020);
  a190=(a030*a007);
  a083=(a083+a190);
  a190=(a083*a052);
  a041=(a041+a190);
  a190=casadi_sq(a020);
  a073=casadi_sq(a007);
  a190=(a190+a073);
  a190=(a190*a000);
  a041=(a041+a190);
  if (res[2]!=0) res[2][53]=a041;
  a041=(a030*a087);
  a190=(a039*a077);
  a041=(a041-a190);
  a190=(a084*a039);
  a041=(a041-a190);
  a190=(a079*a030);
  a041=(a041+a190);
  a190=(a039*a277);
  a041=(a041+a190);
  a190=(a030*a116);
  a041=(a041-a190);
  a190=casadi_sq(a039);
  a073=casadi_sq(a030);
  a190=(a190+a073);
  a190=(a190*a052);
  a041=(a041+a190);
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
  a216=(a008*a216);
  a039=(a038*a039);
  a216=(a216+a039);
  a042=(a028*a042);
  a216=(a216+a042);
  a216=(-a216);
  if (res[2]!=0) res[2][64]=a216;
  a216=(a038+a028);
  a216=(a216+a001);
  a216=(a216+a061);
  a216=(-a216);
  if (res[2]!=0) res[2][65]=a216;
  a216=(a038+a028);
  a216=(a216+a001);
  a216=(-a216);
  if (res[2]!=0) res[2][66]=a216;
  a216=cos(a003);
  a269=(a048*a269);
  a035=(a094*a035);
  a017=(a096*a017);
  a035=(a035+a017);
  a269=(a269-a035);
  a268=(a032*a268);
  a269=(a269+a268);
  a269=(a216*a269);
  a003=sin(a003);
  a105=(a045*a105);
  a102=(a101*a102);
  a105=(a105+a102);
  a233=(a048*a233);
  a105=(a105+a233);
  a247=(a032*a247);
  a105=(a105+a247);
  a105=(a003*a105);
  a269=(a269-a105);
  a105=cos(a009);
  a247=(a057*a256);
  a025=(a093*a025);
  a067=(a074*a067);
  a025=(a025+a067);
  a247=(a247-a025);
  a266=(a029*a266);
  a247=(a247+a266);
  a192=(a008*a192);
  a247=(a247+a192);
  a247=(a105*a247);
  a009=sin(a009);
  a270=(a097*a270);
  a090=(a088*a090);
  a270=(a270+a090);
  a256=(a059*a256);
  a270=(a270+a256);
  a015=(a029*a015);
  a270=(a270+a015);
  a027=(a008*a027);
  a270=(a270+a027);
  a270=(a009*a270);
  a247=(a247-a270);
  a247=(a269+a247);
  a270=cos(a005);
  a246=(a070*a246);
  a098=(a098-a246);
  a051=(a062*a051);
  a098=(a098-a051);
  a237=(a002*a237);
  a098=(a098+a237);
  a098=(a270*a098);
  a005=sin(a005);
  a249=(a081*a249);
  a249=(a249-a103);
  a063=(a068*a063);
  a249=(a249+a063);
  a086=(a002*a086);
  a249=(a249+a086);
  a249=(a005*a249);
  a098=(a098-a249);
  a247=(a247+a098);
  if (res[2]!=0) res[2][67]=a247;
  a273=(a048*a273);
  a037=(a094*a037);
  a112=(a096*a112);
  a037=(a037+a112);
  a273=(a273-a037);
  a274=(a032*a274);
  a273=(a273+a274);
  a273=(a216*a273);
  a118=(a045*a118);
  a115=(a101*a115);
  a118=(a118+a115);
  a278=(a048*a278);
  a118=(a118+a278);
  a188=(a032*a188);
  a118=(a118+a188);
  a118=(a003*a118);
  a273=(a273-a118);
  a122=(a122+a120);
  a116=(a108*a116);
  a122=(a122-a116);
  a272=(a093*a272);
  a122=(a122-a272);
  a123=(a074*a123);
  a122=(a122-a123);
  a057=(a057*a149);
  a122=(a122+a057);
  a114=(a029*a114);
  a122=(a122+a114);
  a231=(a008*a231);
  a122=(a122+a231);
  a122=(a105*a122);
  a277=(a111*a277);
  a125=(a125+a044);
  a277=(a277-a125);
  a053=(a097*a053);
  a277=(a277+a053);
  a119=(a088*a119);
  a277=(a277+a119);
  a059=(a059*a149);
  a277=(a277+a059);
  a184=(a029*a184);
  a277=(a277+a184);
  a255=(a008*a255);
  a277=(a277+a255);
  a277=(a009*a277);
  a122=(a122-a277);
  a122=(a273+a122);
  a172=(a002*a172);
  a026=(a070*a026);
  a172=(a172-a026);
  a172=(a270*a172);
  a253=(a081*a253);
  a071=(a002*a071);
  a253=(a253+a071);
  a253=(a005*a253);
  a172=(a172-a253);
  a122=(a122+a172);
  if (res[2]!=0) res[2][68]=a122;
  a122=(a045*a038);
  a172=(a101*a028);
  a122=(a122+a172);
  a122=(a003*a122);
  a276=(a048*a276);
  a117=(a032*a117);
  a276=(a276+a117);
  a276=(a216*a276);
  a122=(a122-a276);
  a271=(a097*a271);
  a276=(a088*a001);
  a271=(a271+a276);
  a271=(a009*a271);
  a276=(a108*a052);
  a275=(a029*a275);
  a276=(a276+a275);
  a259=(a008*a259);
  a276=(a276+a259);
  a276=(a105*a276);
  a271=(a271-a276);
  a271=(a122+a271);
  a085=(a081*a085);
  a124=(a124+a085);
  a124=(a005*a124);
  a062=(a062*a000);
  a254=(a002*a254);
  a062=(a062+a254);
  a062=(a270*a062);
  a124=(a124-a062);
  a271=(a271+a124);
  if (res[2]!=0) res[2][69]=a271;
  a271=(a094*a038);
  a124=(a096*a028);
  a271=(a271+a124);
  a271=(a216*a271);
  a279=(a048*a279);
  a047=(a032*a047);
  a279=(a279+a047);
  a279=(a003*a279);
  a271=(a271+a279);
  a282=(a093*a282);
  a279=(a074*a001);
  a282=(a282+a279);
  a282=(a105*a282);
  a279=(a111*a052);
  a280=(a029*a280);
  a279=(a279+a280);
  a239=(a008*a239);
  a279=(a279+a239);
  a279=(a009*a279);
  a282=(a282+a279);
  a282=(a271+a282);
  a244=(a070*a244);
  a024=(a024+a244);
  a024=(a270*a024);
  a068=(a068*a000);
  a049=(a002*a049);
  a068=(a068+a049);
  a068=(a005*a068);
  a024=(a024+a068);
  a282=(a282+a024);
  a282=(-a282);
  if (res[2]!=0) res[2][70]=a282;
  a045=(a045*a038);
  a101=(a101*a028);
  a045=(a045+a101);
  a045=(a003*a045);
  a284=(a048*a284);
  a285=(a032*a285);
  a284=(a284+a285);
  a284=(a216*a284);
  a045=(a045-a284);
  a097=(a097*a281);
  a088=(a088*a001);
  a097=(a097+a088);
  a097=(a009*a097);
  a108=(a108*a052);
  a286=(a029*a286);
  a108=(a108+a286);
  a262=(a008*a262);
  a108=(a108+a262);
  a108=(a105*a108);
  a097=(a097-a108);
  a097=(a045+a097);
  a081=(a081*a243);
  a081=(a005*a081);
  a258=(a002*a258);
  a258=(a270*a258);
  a081=(a081-a258);
  a097=(a097+a081);
  if (res[2]!=0) res[2][71]=a097;
  a094=(a094*a038);
  a096=(a096*a028);
  a094=(a094+a096);
  a216=(a216*a094);
  a048=(a048*a283);
  a032=(a032*a287);
  a048=(a048+a032);
  a003=(a003*a048);
  a216=(a216+a003);
  a093=(a093*a290);
  a074=(a074*a001);
  a093=(a093+a074);
  a105=(a105*a093);
  a111=(a111*a052);
  a029=(a029*a288);
  a111=(a111+a029);
  a008=(a008*a265);
  a111=(a111+a008);
  a009=(a009*a111);
  a105=(a105+a009);
  a105=(a216+a105);
  a070=(a070*a267);
  a270=(a270*a070);
  a002=(a002*a264);
  a005=(a005*a002);
  a270=(a270+a005);
  a105=(a105+a270);
  a105=(-a105);
  if (res[2]!=0) res[2][72]=a105;
  a105=(a064<=a156);
  a270=(a156<=a064);
  a270=(a270+a105);
  a105=(a105/a270);
  a270=(a036*a066);
  a005=(a175*a270);
  a005=(a105*a005);
  a002=(a155*a005);
  a264=(a150*a002);
  a070=(a264/a139);
  a070=(a128*a070);
  a131=(2.*a131);
  a070=(a070/a131);
  a267=(a070/a130);
  a009=(a066*a267);
  a129=(a129/a130);
  a070=(a129*a070);
  a009=(a009-a070);
  a111=(a152<=a095);
  a095=(a095<=a152);
  a095=(a095+a111);
  a111=(a111/a095);
  a095=(a154-a126);
  a095=pow(a153,a095);
  a095=(a154*a095);
  a005=(a151*a005);
  a008=(a095*a005);
  a008=(a111*a008);
  a009=(a009-a008);
  a009=(a127?a009:0);
  a104=(2.*a104);
  a265=(a014<=a076);
  a076=(a076<=a014);
  a076=(a265+a076);
  a265=(a265/a076);
  a091=(2.*a091);
  a076=(a008/a091);
  a076=(a127?a076:0);
  a054=pow(a054,a163);
  a054=(a109*a054);
  a002=(a132*a002);
  a014=(a146*a002);
  a029=(a023*a014);
  a029=(a050*a029);
  a014=(a110*a014);
  a014=(a055*a014);
  a029=(a029+a014);
  a029=(a127?a029:0);
  a270=(a157*a270);
  a014=(a162*a270);
  a288=casadi_sign(a075);
  a052=(a064<=a013);
  a093=(a013<=a064);
  a093=(a093+a052);
  a052=(a052/a093);
  a093=(a046<=a126);
  a046=(a126<=a046);
  a046=(a046+a093);
  a093=(a093/a046);
  a046=(a166*a066);
  a046=(a093*a046);
  a046=(a052*a046);
  a074=(a046/a043);
  a001=(a160<=a106);
  a106=(a106<=a160);
  a160=(a106+a001);
  a001=(a001/a160);
  a162=(a162/a161);
  a270=(a075*a270);
  a162=(a162*a270);
  a290=(a001*a162);
  a290=(a074-a290);
  a290=(a288*a290);
  a014=(a014+a290);
  a290=(a110*a014);
  a290=(a050*a290);
  a029=(a029-a290);
  a290=(a023*a014);
  a290=(a055*a290);
  a029=(a029+a290);
  a029=(a054*a029);
  a076=(a076+a029);
  a076=(a265*a076);
  a076=(a104*a076);
  a029=(a033*a076);
  a009=(a009+a029);
  if (res[2]!=0) res[2][73]=a009;
  a009=(a016*a055);
  a029=(a036*a050);
  a290=(a185*a029);
  a009=(a009-a290);
  a009=(a105*a009);
  a290=(a155*a009);
  a003=(a150*a290);
  a048=(a003/a139);
  a048=(a128*a048);
  a048=(a048/a131);
  a032=(a048/a130);
  a287=(a066*a032);
  a048=(a129*a048);
  a287=(a287-a048);
  a009=(a151*a009);
  a283=(a095*a009);
  a283=(a111*a283);
  a287=(a287-a283);
  a287=(a127?a287:0);
  a094=(a283/a091);
  a094=(a127?a094:0);
  a096=(a157*a055);
  a029=(a157*a029);
  a028=(a075*a029);
  a038=(a028/a161);
  a097=(a158*a038);
  a096=(a096-a097);
  a290=(a132*a290);
  a097=(a146*a290);
  a081=(a023*a097);
  a081=(a050*a081);
  a081=(a127?a081:0);
  a096=(a096+a081);
  a097=(a110*a097);
  a097=(a055*a097);
  a097=(a127?a097:0);
  a096=(a096+a097);
  a097=(a183/a161);
  a097=(a097*a028);
  a028=(a001*a097);
  a186=(a186*a050);
  a186=(a093*a186);
  a186=(a052*a186);
  a081=(a186/a043);
  a028=(a028-a081);
  a028=(a288*a028);
  a183=(a183*a029);
  a028=(a028-a183);
  a183=(a110*a028);
  a183=(a050*a183);
  a096=(a096-a183);
  a183=(a023*a028);
  a183=(a055*a183);
  a096=(a096+a183);
  a096=(a054*a096);
  a094=(a094+a096);
  a094=(a265*a094);
  a094=(a104*a094);
  a096=(a033*a094);
  a287=(a287+a096);
  if (res[2]!=0) res[2][74]=a287;
  a287=(a036*a055);
  a096=(a168*a287);
  a183=(a016*a050);
  a096=(a096+a183);
  a105=(a105*a096);
  a096=(a155*a105);
  a150=(a150*a096);
  a183=(a150/a139);
  a183=(a128*a183);
  a183=(a183/a131);
  a130=(a183/a130);
  a131=(a066*a130);
  a129=(a129*a183);
  a131=(a131-a129);
  a151=(a151*a105);
  a095=(a095*a151);
  a111=(a111*a095);
  a131=(a131-a111);
  a131=(a127?a131:0);
  a091=(a111/a091);
  a091=(a127?a091:0);
  a287=(a157*a287);
  a075=(a075*a287);
  a095=(a075/a161);
  a105=(a158*a095);
  a157=(a157*a050);
  a105=(a105+a157);
  a096=(a132*a096);
  a157=(a146*a096);
  a183=(a023*a157);
  a183=(a050*a183);
  a183=(a127?a183:0);
  a105=(a105+a183);
  a157=(a110*a157);
  a157=(a055*a157);
  a157=(a127?a157:0);
  a105=(a105+a157);
  a287=(a187*a287);
  a177=(a177*a055);
  a093=(a093*a177);
  a052=(a052*a093);
  a093=(a052/a043);
  a187=(a187/a161);
  a187=(a187*a075);
  a001=(a001*a187);
  a001=(a093-a001);
  a288=(a288*a001);
  a287=(a287+a288);
  a110=(a110*a287);
  a110=(a050*a110);
  a105=(a105-a110);
  a023=(a023*a287);
  a023=(a055*a023);
  a105=(a105+a023);
  a054=(a054*a105);
  a091=(a091+a054);
  a265=(a265*a091);
  a104=(a104*a265);
  a265=(a033*a104);
  a131=(a131+a265);
  if (res[2]!=0) res[2][75]=a131;
  a166=(a166*a036);
  a070=(a127?a070:0);
  a166=(a166+a070);
  a267=(a018*a267);
  a267=(a127?a267:0);
  a166=(a166+a267);
  a008=(a127?a008:0);
  a166=(a166+a008);
  a076=(a107*a076);
  a166=(a166+a076);
  a014=(a065*a014);
  a166=(a166+a014);
  if (res[2]!=0) res[2][76]=a166;
  a032=(a018*a032);
  a048=(a048+a032);
  a048=(a048+a283);
  a048=(a127?a048:0);
  a094=(a107*a094);
  a048=(a048+a094);
  a028=(a065*a028);
  a048=(a048+a028);
  if (res[2]!=0) res[2][77]=a048;
  a018=(a018*a130);
  a129=(a129+a018);
  a129=(a129+a111);
  a129=(a127?a129:0);
  a104=(a107*a104);
  a129=(a129+a104);
  a287=(a065*a287);
  a129=(a129+a287);
  if (res[2]!=0) res[2][78]=a129;
  a134=(a134/a135);
  a139=(a132/a139);
  a264=(a139*a264);
  a129=(a134*a264);
  a129=(a127?a129:0);
  if (res[2]!=0) res[2][79]=a129;
  a003=(a139*a003);
  a129=(a134*a003);
  a129=(a127?a129:0);
  if (res[2]!=0) res[2][80]=a129;
  a139=(a139*a150);
  a134=(a134*a139);
  a134=(a127?a134:0);
  if (res[2]!=0) res[2][81]=a134;
  a133=(2.*a133);
  a134=(a264/a135);
  a134=(a133*a134);
  a134=(a127?a134:0);
  if (res[2]!=0) res[2][82]=a134;
  a134=(a003/a135);
  a134=(a133*a134);
  a134=(a127?a134:0);
  if (res[2]!=0) res[2][83]=a134;
  a135=(a139/a135);
  a133=(a133*a135);
  a133=(a127?a133:0);
  if (res[2]!=0) res[2][84]=a133;
  a137=(a137/a138);
  a133=(a137*a264);
  a133=(a127?a133:0);
  if (res[2]!=0) res[2][85]=a133;
  a133=(a137*a003);
  a133=(a127?a133:0);
  if (res[2]!=0) res[2][86]=a133;
  a137=(a137*a139);
  a137=(a127?a137:0);
  if (res[2]!=0) res[2][87]=a137;
  a136=(2.*a136);
  a264=(a264/a138);
  a264=(a136*a264);
  a264=(a127?a264:0);
  if (res[2]!=0) res[2][88]=a264;
  a003=(a003/a138);
  a003=(a136*a003);
  a003=(a127?a003:0);
  if (res[2]!=0) res[2][89]=a003;
  a139=(a139/a138);
  a136=(a136*a139);
  a136=(a127?a136:0);
  if (res[2]!=0) res[2][90]=a136;
  a201=(a201/a202);
  a136=(a064<=a221);
  a139=(a221<=a064);
  a139=(a139+a136);
  a136=(a136/a139);
  a139=(a173-a167);
  a138=(a197*a139);
  a003=(a240*a138);
  a003=(a136*a003);
  a264=(a220*a003);
  a137=(a217*a264);
  a133=(a137/a211);
  a133=(a128*a133);
  a203=(2.*a203);
  a133=(a133/a203);
  a135=(a201*a133);
  a134=(-a135);
  a134=(a200?a134:0);
  a150=(a228*a197);
  a134=(a134-a150);
  a133=(a133/a202);
  a129=(a173*a133);
  a129=(a200?a129:0);
  a134=(a134+a129);
  a129=(a152<=a199);
  a199=(a199<=a152);
  a199=(a199+a129);
  a129=(a129/a199);
  a199=(a154-a126);
  a199=pow(a219,a199);
  a154=(a154*a199);
  a003=(a218*a003);
  a199=(a154*a003);
  a199=(a129*a199);
  a152=(-a199);
  a152=(a200?a152:0);
  a134=(a134+a152);
  a138=(a222*a138);
  a152=(a225*a138);
  a287=(a065*a152);
  a134=(a134-a287);
  a189=(2.*a189);
  a287=(a178<=a169);
  a169=(a169<=a178);
  a169=(a287+a169);
  a287=(a287/a169);
  a198=(2.*a198);
  a169=(a199/a198);
  a169=(a200?a169:0);
  a165=pow(a165,a163);
  a109=(a109*a165);
  a264=(a204*a264);
  a165=(a140*a264);
  a163=(a193*a165);
  a163=(a179*a163);
  a165=(a191*a165);
  a165=(a174*a165);
  a163=(a163+a165);
  a163=(a200?a163:0);
  a165=(a191*a152);
  a165=(a179*a165);
  a163=(a163-a165);
  a165=(a193*a152);
  a165=(a174*a165);
  a163=(a163+a165);
  a164=casadi_sign(a164);
  a165=(a064<=a195);
  a178=(a195<=a064);
  a178=(a178+a165);
  a165=(a165/a178);
  a178=(a196<=a126);
  a126=(a126<=a196);
  a126=(a126+a178);
  a178=(a178/a126);
  a139=(a228*a139);
  a139=(a178*a139);
  a139=(a165*a139);
  a126=(a139/a043);
  a196=(a223<=a194);
  a194=(a194<=a223);
  a223=(a194+a196);
  a196=(a196/a223);
  a104=(a225/a224);
  a138=(a232*a138);
  a111=(a104*a138);
  a018=(a196*a111);
  a018=(a126-a018);
  a018=(a164*a018);
  a130=(a193*a018);
  a130=(a174*a130);
  a163=(a163-a130);
  a130=(a191*a018);
  a130=(a179*a130);
  a163=(a163+a130);
  a163=(a109*a163);
  a169=(a169+a163);
  a169=(a287*a169);
  a169=(a189*a169);
  a163=(a033*a169);
  a134=(a134+a163);
  a163=(a065*a018);
  a134=(a134+a163);
  if (res[2]!=0) res[2][91]=a134;
  a134=(a197*a173);
  a163=(a240*a134);
  a163=(a136*a163);
  a130=(a220*a163);
  a048=(a217*a130);
  a028=(a048/a211);
  a028=(a128*a028);
  a028=(a028/a203);
  a094=(a028/a202);
  a283=(a173*a094);
  a028=(a201*a028);
  a283=(a283-a028);
  a163=(a218*a163);
  a032=(a154*a163);
  a032=(a129*a032);
  a283=(a283-a032);
  a283=(a200?a283:0);
  a134=(a222*a134);
  a225=(a225*a134);
  a166=(a065*a225);
  a283=(a283-a166);
  a166=(a032/a198);
  a166=(a200?a166:0);
  a130=(a204*a130);
  a014=(a140*a130);
  a076=(a193*a014);
  a076=(a179*a076);
  a014=(a191*a014);
  a014=(a174*a014);
  a076=(a076+a014);
  a076=(a200?a076:0);
  a014=(a191*a225);
  a014=(a179*a014);
  a076=(a076-a014);
  a014=(a193*a225);
  a014=(a174*a014);
  a076=(a076+a014);
  a228=(a228*a173);
  a228=(a178*a228);
  a228=(a165*a228);
  a014=(a228/a043);
  a134=(a232*a134);
  a104=(a104*a134);
  a008=(a196*a104);
  a008=(a014-a008);
  a008=(a164*a008);
  a267=(a193*a008);
  a267=(a174*a267);
  a076=(a076-a267);
  a267=(a191*a008);
  a267=(a179*a267);
  a076=(a076+a267);
  a076=(a109*a076);
  a166=(a166+a076);
  a166=(a287*a166);
  a166=(a189*a166);
  a076=(a033*a166);
  a283=(a283+a076);
  a076=(a065*a008);
  a283=(a283+a076);
  if (res[2]!=0) res[2][92]=a283;
  a283=(a180*a174);
  a076=(a197*a179);
  a267=(a250*a076);
  a283=(a283-a267);
  a283=(a136*a283);
  a267=(a220*a283);
  a070=(a217*a267);
  a131=(a070/a211);
  a131=(a128*a131);
  a131=(a131/a203);
  a265=(a131/a202);
  a091=(a173*a265);
  a131=(a201*a131);
  a091=(a091-a131);
  a283=(a218*a283);
  a054=(a154*a283);
  a054=(a129*a054);
  a091=(a091-a054);
  a091=(a200?a091:0);
  a076=(a222*a076);
  a105=(a248*a076);
  a023=(a065*a105);
  a091=(a091+a023);
  a023=(a054/a198);
  a023=(a200?a023:0);
  a110=(a222*a174);
  a076=(a232*a076);
  a288=(a076/a224);
  a001=(a158*a288);
  a110=(a110-a001);
  a267=(a204*a267);
  a001=(a140*a267);
  a075=(a193*a001);
  a075=(a179*a075);
  a075=(a200?a075:0);
  a110=(a110+a075);
  a001=(a191*a001);
  a001=(a174*a001);
  a001=(a200?a001:0);
  a110=(a110+a001);
  a001=(a191*a105);
  a001=(a179*a001);
  a110=(a110+a001);
  a001=(a193*a105);
  a001=(a174*a001);
  a110=(a110-a001);
  a248=(a248/a224);
  a248=(a248*a076);
  a076=(a196*a248);
  a251=(a251*a179);
  a251=(a178*a251);
  a251=(a165*a251);
  a001=(a251/a043);
  a076=(a076-a001);
  a076=(a164*a076);
  a075=(a193*a076);
  a075=(a174*a075);
  a110=(a110-a075);
  a075=(a191*a076);
  a075=(a179*a075);
  a110=(a110+a075);
  a110=(a109*a110);
  a023=(a023+a110);
  a023=(a287*a023);
  a023=(a189*a023);
  a110=(a033*a023);
  a091=(a091+a110);
  a110=(a065*a076);
  a091=(a091+a110);
  if (res[2]!=0) res[2][93]=a091;
  a091=(a197*a174);
  a110=(a230*a091);
  a075=(a180*a179);
  a110=(a110+a075);
  a136=(a136*a110);
  a110=(a220*a136);
  a217=(a217*a110);
  a075=(a217/a211);
  a128=(a128*a075);
  a128=(a128/a203);
  a202=(a128/a202);
  a203=(a173*a202);
  a201=(a201*a128);
  a203=(a203-a201);
  a218=(a218*a136);
  a154=(a154*a218);
  a129=(a129*a154);
  a203=(a203-a129);
  a203=(a200?a203:0);
  a091=(a222*a091);
  a154=(a252*a091);
  a136=(a065*a154);
  a203=(a203-a136);
  a198=(a129/a198);
  a198=(a200?a198:0);
  a232=(a232*a091);
  a091=(a232/a224);
  a158=(a158*a091);
  a222=(a222*a179);
  a158=(a158+a222);
  a110=(a204*a110);
  a222=(a140*a110);
  a136=(a193*a222);
  a136=(a179*a136);
  a136=(a200?a136:0);
  a158=(a158+a136);
  a222=(a191*a222);
  a222=(a174*a222);
  a222=(a200?a222:0);
  a158=(a158+a222);
  a222=(a191*a154);
  a222=(a179*a222);
  a158=(a158-a222);
  a222=(a193*a154);
  a222=(a174*a222);
  a158=(a158+a222);
  a242=(a242*a174);
  a178=(a178*a242);
  a165=(a165*a178);
  a178=(a165/a043);
  a252=(a252/a224);
  a252=(a252*a232);
  a196=(a196*a252);
  a196=(a178-a196);
  a164=(a164*a196);
  a193=(a193*a164);
  a193=(a174*a193);
  a158=(a158-a193);
  a191=(a191*a164);
  a191=(a179*a191);
  a158=(a158+a191);
  a109=(a109*a158);
  a198=(a198+a109);
  a287=(a287*a198);
  a189=(a189*a287);
  a033=(a033*a189);
  a203=(a203+a033);
  a065=(a065*a164);
  a203=(a203+a065);
  if (res[2]!=0) res[2][94]=a203;
  a135=(a200?a135:0);
  a135=(a150+a135);
  a133=(a167*a133);
  a133=(a200?a133:0);
  a135=(a135+a133);
  a199=(a200?a199:0);
  a135=(a135+a199);
  a152=(a072*a152);
  a135=(a135+a152);
  a169=(a107*a169);
  a135=(a135+a169);
  a018=(a072*a018);
  a135=(a135-a018);
  if (res[2]!=0) res[2][95]=a135;
  a028=(a200?a028:0);
  a150=(a150+a028);
  a094=(a167*a094);
  a094=(a200?a094:0);
  a150=(a150+a094);
  a032=(a200?a032:0);
  a150=(a150+a032);
  a225=(a072*a225);
  a150=(a150+a225);
  a166=(a107*a166);
  a150=(a150+a166);
  a008=(a072*a008);
  a150=(a150-a008);
  if (res[2]!=0) res[2][96]=a150;
  a265=(a167*a265);
  a131=(a131+a265);
  a131=(a131+a054);
  a131=(a200?a131:0);
  a105=(a072*a105);
  a131=(a131-a105);
  a023=(a107*a023);
  a131=(a131+a023);
  a076=(a072*a076);
  a131=(a131-a076);
  if (res[2]!=0) res[2][97]=a131;
  a202=(a167*a202);
  a201=(a201+a202);
  a201=(a201+a129);
  a201=(a200?a201:0);
  a154=(a072*a154);
  a201=(a201+a154);
  a107=(a107*a189);
  a201=(a201+a107);
  a072=(a072*a164);
  a201=(a201-a072);
  if (res[2]!=0) res[2][98]=a201;
  a206=(a206/a207);
  a211=(a204/a211);
  a137=(a211*a137);
  a201=(a206*a137);
  a201=(a200?a201:0);
  if (res[2]!=0) res[2][99]=a201;
  a048=(a211*a048);
  a201=(a206*a048);
  a201=(a200?a201:0);
  if (res[2]!=0) res[2][100]=a201;
  a070=(a211*a070);
  a201=(a206*a070);
  a201=(a200?a201:0);
  if (res[2]!=0) res[2][101]=a201;
  a211=(a211*a217);
  a206=(a206*a211);
  a206=(a200?a206:0);
  if (res[2]!=0) res[2][102]=a206;
  a205=(2.*a205);
  a206=(a137/a207);
  a206=(a205*a206);
  a206=(a200?a206:0);
  if (res[2]!=0) res[2][103]=a206;
  a206=(a048/a207);
  a206=(a205*a206);
  a206=(a200?a206:0);
  if (res[2]!=0) res[2][104]=a206;
  a206=(a070/a207);
  a206=(a205*a206);
  a206=(a200?a206:0);
  if (res[2]!=0) res[2][105]=a206;
  a207=(a211/a207);
  a205=(a205*a207);
  a205=(a200?a205:0);
  if (res[2]!=0) res[2][106]=a205;
  a209=(a209/a210);
  a205=(a209*a137);
  a205=(a200?a205:0);
  if (res[2]!=0) res[2][107]=a205;
  a205=(a209*a048);
  a205=(a200?a205:0);
  if (res[2]!=0) res[2][108]=a205;
  a205=(a209*a070);
  a205=(a200?a205:0);
  if (res[2]!=0) res[2][109]=a205;
  a209=(a209*a211);
  a209=(a200?a209:0);
  if (res[2]!=0) res[2][110]=a209;
  a208=(2.*a208);
  a137=(a137/a210);
  a137=(a208*a137);
  a137=(a200?a137:0);
  if (res[2]!=0) res[2][111]=a137;
  a048=(a048/a210);
  a048=(a208*a048);
  a048=(a200?a048:0);
  if (res[2]!=0) res[2][112]=a048;
  a070=(a070/a210);
  a070=(a208*a070);
  a070=(a200?a070:0);
  if (res[2]!=0) res[2][113]=a070;
  a211=(a211/a210);
  a208=(a208*a211);
  a208=(a200?a208:0);
  if (res[2]!=0) res[2][114]=a208;
  if (res[2]!=0) res[2][115]=a269;
  if (res[2]!=0) res[2][116]=a273;
  if (res[2]!=0) res[2][117]=a122;
  a271=(-a271);
  if (res[2]!=0) res[2][118]=a271;
  if (res[2]!=0) res[2][119]=a045;
  a216=(-a216);
  if (res[2]!=0) res[2][120]=a216;
  a219=log(a219);
  a219=(a219*a220);
  a003=(a219*a003);
  a003=(a200?a003:0);
  a153=log(a153);
  a153=(a153*a155);
  a005=(a153*a005);
  a005=(a127?a005:0);
  a003=(a003+a005);
  if (res[2]!=0) res[2][121]=a003;
  a163=(a219*a163);
  a163=(a200?a163:0);
  if (res[2]!=0) res[2][122]=a163;
  a009=(a153*a009);
  a009=(a127?a009:0);
  if (res[2]!=0) res[2][123]=a009;
  a153=(a153*a151);
  a153=(a127?a153:0);
  if (res[2]!=0) res[2][124]=a153;
  a283=(a219*a283);
  a283=(a200?a283:0);
  if (res[2]!=0) res[2][125]=a283;
  a219=(a219*a218);
  a219=(a200?a219:0);
  if (res[2]!=0) res[2][126]=a219;
  a142=(2.*a142);
  a264=(a215*a264);
  a219=(a264/a213);
  a219=(a200?a219:0);
  a002=(a148*a002);
  a218=(a002/a145);
  a218=(a127?a218:0);
  a219=(a219+a218);
  a219=(a141*a219);
  a219=(a142*a219);
  if (res[2]!=0) res[2][127]=a219;
  a130=(a215*a130);
  a219=(a130/a213);
  a219=(a141*a219);
  a219=(a142*a219);
  a219=(a200?a219:0);
  if (res[2]!=0) res[2][128]=a219;
  a290=(a148*a290);
  a219=(a290/a145);
  a219=(a141*a219);
  a219=(a142*a219);
  a219=(a127?a219:0);
  if (res[2]!=0) res[2][129]=a219;
  a096=(a148*a096);
  a219=(a096/a145);
  a219=(a141*a219);
  a219=(a142*a219);
  a219=(a127?a219:0);
  if (res[2]!=0) res[2][130]=a219;
  a267=(a215*a267);
  a219=(a267/a213);
  a219=(a141*a219);
  a219=(a142*a219);
  a219=(a200?a219:0);
  if (res[2]!=0) res[2][131]=a219;
  a110=(a215*a110);
  a219=(a110/a213);
  a141=(a141*a219);
  a142=(a142*a141);
  a142=(a200?a142:0);
  if (res[2]!=0) res[2][132]=a142;
  a142=(a212<=a144);
  a141=(a144<=a212);
  a141=(a141+a142);
  a142=(a142/a141);
  a141=(a140/a213);
  a264=(a141*a264);
  a264=(a142*a264);
  a264=(-a264);
  a264=(a200?a264:0);
  a219=(a143<=a144);
  a218=(a144<=a143);
  a218=(a218+a219);
  a219=(a219/a218);
  a218=(a146/a145);
  a002=(a218*a002);
  a002=(a219*a002);
  a002=(-a002);
  a002=(a127?a002:0);
  a264=(a264+a002);
  if (res[2]!=0) res[2][133]=a264;
  a130=(a141*a130);
  a130=(a142*a130);
  a130=(-a130);
  a130=(a200?a130:0);
  if (res[2]!=0) res[2][134]=a130;
  a290=(a218*a290);
  a290=(a219*a290);
  a290=(-a290);
  a290=(a127?a290:0);
  if (res[2]!=0) res[2][135]=a290;
  a218=(a218*a096);
  a219=(a219*a218);
  a219=(-a219);
  a219=(a127?a219:0);
  if (res[2]!=0) res[2][136]=a219;
  a267=(a141*a267);
  a267=(a142*a267);
  a267=(-a267);
  a267=(a200?a267:0);
  if (res[2]!=0) res[2][137]=a267;
  a141=(a141*a110);
  a142=(a142*a141);
  a142=(-a142);
  a142=(a200?a142:0);
  if (res[2]!=0) res[2][138]=a142;
  a138=(a138/a224);
  a270=(a270/a161);
  a138=(a138+a270);
  if (res[2]!=0) res[2][139]=a138;
  a134=(a134/a224);
  if (res[2]!=0) res[2][140]=a134;
  a038=(a016*a038);
  a038=(-a038);
  if (res[2]!=0) res[2][141]=a038;
  a095=(a016*a095);
  if (res[2]!=0) res[2][142]=a095;
  a288=(a180*a288);
  a288=(-a288);
  if (res[2]!=0) res[2][143]=a288;
  a091=(a180*a091);
  if (res[2]!=0) res[2][144]=a091;
  a195=(a195/a043);
  a139=(a195*a139);
  a013=(a013/a043);
  a046=(a013*a046);
  a139=(a139+a046);
  a046=(a056<=a092);
  a043=(a092<=a056);
  a091=(a046+a043);
  a046=(a046/a091);
  a194=(a194/a223);
  a111=(a194*a111);
  a223=(a046*a111);
  a126=(a126+a223);
  a126=(a139-a126);
  a126=(a126-a074);
  a074=(a056<=a092);
  a092=(a092<=a056);
  a056=(a074+a092);
  a074=(a074/a056);
  a106=(a106/a160);
  a162=(a106*a162);
  a160=(a074*a162);
  a126=(a126-a160);
  if (res[2]!=0) res[2][145]=a126;
  a228=(a195*a228);
  a104=(a194*a104);
  a126=(a046*a104);
  a014=(a014+a126);
  a014=(a228-a014);
  if (res[2]!=0) res[2][146]=a014;
  a186=(a013*a186);
  a081=(a081-a186);
  a097=(a106*a097);
  a014=(a074*a097);
  a081=(a081+a014);
  if (res[2]!=0) res[2][147]=a081;
  a013=(a013*a052);
  a093=(a013-a093);
  a106=(a106*a187);
  a074=(a074*a106);
  a093=(a093-a074);
  if (res[2]!=0) res[2][148]=a093;
  a248=(a194*a248);
  a093=(a046*a248);
  a001=(a001+a093);
  a251=(a195*a251);
  a001=(a001-a251);
  if (res[2]!=0) res[2][149]=a001;
  a195=(a195*a165);
  a194=(a194*a252);
  a046=(a046*a194);
  a178=(a178+a046);
  a178=(a195-a178);
  if (res[2]!=0) res[2][150]=a178;
  a043=(a043/a091);
  a111=(a043*a111);
  a092=(a092/a056);
  a162=(a092*a162);
  a111=(a111+a162);
  a111=(a159*a111);
  a139=(a139+a111);
  a139=(-a139);
  if (res[2]!=0) res[2][151]=a139;
  a104=(a043*a104);
  a104=(a159*a104);
  a228=(a228+a104);
  a228=(-a228);
  if (res[2]!=0) res[2][152]=a228;
  a097=(a092*a097);
  a097=(a159*a097);
  a186=(a186+a097);
  if (res[2]!=0) res[2][153]=a186;
  a092=(a092*a106);
  a092=(a159*a092);
  a013=(a013+a092);
  a013=(-a013);
  if (res[2]!=0) res[2][154]=a013;
  a248=(a043*a248);
  a248=(a159*a248);
  a251=(a251+a248);
  if (res[2]!=0) res[2][155]=a251;
  a043=(a043*a194);
  a159=(a159*a043);
  a195=(a195+a159);
  a195=(-a195);
  if (res[2]!=0) res[2][156]=a195;
  a195=(a064<=a156);
  a156=(a156<=a064);
  a156=(a156+a195);
  a195=(a195/a156);
  a146=(a146/a145);
  a145=(a144<=a143);
  a143=(a143<=a144);
  a143=(a145+a143);
  a145=(a145/a143);
  a146=(a146*a145);
  a148=(a148*a146);
  a132=(a132*a148);
  a155=(a155*a132);
  a195=(a195*a155);
  a175=(a175*a195);
  a175=(a036*a175);
  a066=(a066*a175);
  a066=(-a066);
  a066=(a127?a066:0);
  if (res[3]!=0) res[3][0]=a066;
  a066=(a016*a195);
  a066=(a055*a066);
  a185=(a185*a195);
  a185=(a036*a185);
  a185=(a050*a185);
  a066=(a066-a185);
  a066=(-a066);
  a066=(a127?a066:0);
  if (res[3]!=0) res[3][1]=a066;
  a016=(a016*a195);
  a050=(a050*a016);
  a168=(a168*a195);
  a036=(a036*a168);
  a055=(a055*a036);
  a050=(a050+a055);
  a050=(-a050);
  a127=(a127?a050:0);
  if (res[3]!=0) res[3][2]=a127;
  a127=(a064<=a221);
  a221=(a221<=a064);
  a221=(a221+a127);
  a127=(a127/a221);
  a140=(a140/a213);
  a213=(a144<=a212);
  a212=(a212<=a144);
  a212=(a213+a212);
  a213=(a213/a212);
  a140=(a140*a213);
  a215=(a215*a140);
  a204=(a204*a215);
  a220=(a220*a204);
  a127=(a127*a220);
  a240=(a240*a127);
  a240=(a197*a240);
  a173=(a173*a240);
  a167=(a167*a240);
  a167=(a173-a167);
  a167=(-a167);
  a167=(a200?a167:0);
  if (res[3]!=0) res[3][3]=a167;
  a173=(-a173);
  a173=(a200?a173:0);
  if (res[3]!=0) res[3][4]=a173;
  a173=(a180*a127);
  a173=(a174*a173);
  a250=(a250*a127);
  a250=(a197*a250);
  a250=(a179*a250);
  a173=(a173-a250);
  a173=(-a173);
  a173=(a200?a173:0);
  if (res[3]!=0) res[3][5]=a173;
  a180=(a180*a127);
  a179=(a179*a180);
  a230=(a230*a127);
  a197=(a197*a230);
  a174=(a174*a197);
  a179=(a179+a174);
  a179=(-a179);
  a200=(a200?a179:0);
  if (res[3]!=0) res[3][6]=a200;
  return 0;
}

/* jac_forward_dynamics:(x[12],tau[2],p[39],v_imp[2],out_xdot[12x1,0nz])->(jac_xdot_x[12x12,78nz],jac_xdot_tau[12x2,12nz],jac_xdot_p[12x39,234nz],jac_xdot_v_imp[12x2,12nz]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real **res1=res+4, *rr, *w00=w+296, *w01=w+302, *w02=w+308, *w03=w+320, *w05=w+322, *w07=w+324, *w08=w+360, *w09=w+412, *w10=w+414, *w11=w+571;
  casadi_real *w12=w+578, *w13=w+650, *w14=w+722, *w15=w+800, *w17=w+878, *w18=w+890, *w19=w+1124;
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
  if (sz_w) *sz_w = 1358;
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 10*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 8*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 40*sizeof(casadi_int);
  if (sz_w) *sz_w = 1358*sizeof(casadi_real);
  return 0;
}

/* contact:(x[12],p[39],v_imp[2])->(delta[2],delta_dot[2],v_t[2],f_n[2],f_t[2],f_x[2],f_y[2],dissipation[2]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34;
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
  a21=(a16<a06);
  a22=1.3333333333333333e+00;
  a23=(a04*a00);
  a04=(a04-a00);
  a23=(a23/a04);
  a23=sqrt(a23);
  a04=(a22*a23);
  a00=1.;
  a24=arg[1]? arg[1][23] : 0;
  a24=casadi_sq(a24);
  a24=(a00-a24);
  a25=arg[1]? arg[1][22] : 0;
  a24=(a24/a25);
  a25=arg[1]? arg[1][25] : 0;
  a25=casadi_sq(a25);
  a25=(a00-a25);
  a26=arg[1]? arg[1][24] : 0;
  a25=(a25/a26);
  a24=(a24+a25);
  a04=(a04/a24);
  a25=7.5000000000000000e-01;
  a26=-7.5000000000000000e-01;
  a27=arg[1]? arg[1][34] : 0;
  a27=casadi_sq(a27);
  a26=(a26*a27);
  a25=(a25+a26);
  a26=arg[2]? arg[2][0] : 0;
  a27=arg[1]? arg[1][35] : 0;
  a26=casadi_fmax(a26,a27);
  a26=(a25/a26);
  a26=(a26*a13);
  a26=(a00+a26);
  a04=(a04*a26);
  a26=1.0000000000000000e-300;
  a06=casadi_fmax(a26,a06);
  a28=arg[1]? arg[1][33] : 0;
  a06=pow(a06,a28);
  a04=(a04*a06);
  a04=(a21?a04:0);
  a04=casadi_fmax(a16,a04);
  if (res[3]!=0) res[3][0]=a04;
  a29=(a16<a10);
  a30=(a09*a08);
  a31=(a09-a08);
  a30=(a30/a31);
  a30=sqrt(a30);
  a22=(a22*a30);
  a31=arg[1]? arg[1][29] : 0;
  a31=casadi_sq(a31);
  a31=(a00-a31);
  a32=arg[1]? arg[1][28] : 0;
  a31=(a31/a32);
  a32=arg[1]? arg[1][31] : 0;
  a32=casadi_sq(a32);
  a32=(a00-a32);
  a33=arg[1]? arg[1][30] : 0;
  a32=(a32/a33);
  a31=(a31+a32);
  a22=(a22/a31);
  a32=arg[2]? arg[2][1] : 0;
  a32=casadi_fmax(a32,a27);
  a25=(a25/a32);
  a25=(a25*a12);
  a25=(a00+a25);
  a22=(a22*a25);
  a26=casadi_fmax(a26,a10);
  a26=pow(a26,a28);
  a22=(a22*a26);
  a22=(a29?a22:0);
  a22=casadi_fmax(a16,a22);
  if (res[3]!=0) res[3][1]=a22;
  a28=arg[1]? arg[1][36] : 0;
  a10=arg[1]? arg[1][37] : 0;
  a25=1.0000000000000000e-03;
  a32=arg[1]? arg[1][38] : 0;
  a25=(a25*a32);
  a27=casadi_fmax(a10,a25);
  a33=casadi_fabs(a19);
  a27=casadi_fmax(a27,a33);
  a34=(a28/a27);
  a34=(a34*a19);
  a34=(a34*a04);
  a33=(a33-a10);
  a32=(a32-a10);
  a33=(a33/a32);
  a33=casadi_fmax(a16,a33);
  a33=casadi_fmin(a00,a33);
  a34=(a34*a33);
  a34=(-a34);
  if (res[4]!=0) res[4][0]=a34;
  a25=casadi_fmax(a10,a25);
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
  a25=casadi_fmax(a25,a09);
  a08=(a28/a25);
  a08=(a08*a14);
  a08=(a08*a22);
  a09=(a09-a10);
  a09=(a09/a32);
  a16=casadi_fmax(a16,a09);
  a00=casadi_fmin(a00,a16);
  a08=(a08*a00);
  a08=(-a08);
  if (res[4]!=0) res[4][1]=a08;
  a08=(a28*a02);
  a08=(a08/a27);
  a08=(a08*a19);
  a08=(a08*a04);
  a08=(a08*a33);
  a08=(a08*a07);
  a16=(a02*a04);
  a16=(a16*a05);
  a08=(a08-a16);
  if (res[5]!=0) res[5][0]=a08;
  a08=(a28*a01);
  a08=(a08/a25);
  a08=(a08*a14);
  a08=(a08*a22);
  a08=(a08*a00);
  a08=(a08*a11);
  a16=(a01*a22);
  a16=(a16*a03);
  a08=(a08-a16);
  if (res[5]!=0) res[5][1]=a08;
  a08=(a02*a04);
  a08=(a08*a07);
  a02=(a28*a02);
  a02=(a02/a27);
  a02=(a02*a19);
  a02=(a02*a04);
  a02=(a02*a33);
  a02=(a02*a05);
  a08=(a08+a02);
  a08=(-a08);
  if (res[6]!=0) res[6][0]=a08;
  a08=(a01*a22);
  a08=(a08*a11);
  a01=(a28*a01);
  a01=(a01/a25);
  a01=(a01*a14);
  a01=(a01*a22);
  a01=(a01*a00);
  a01=(a01*a03);
  a08=(a08+a01);
  a08=(-a08);
  if (res[6]!=0) res[6][1]=a08;
  a08=-1.3333333333333333e+00;
  a23=(a08*a23);
  a23=(a23/a24);
  a23=(a23*a06);
  a21=(a21?a23:0);
  a21=(a21+a04);
  a13=(a13*a21);
  a19=casadi_sq(a19);
  a19=(a28*a19);
  a19=(a19/a27);
  a19=(a19*a04);
  a19=(a19*a33);
  a13=(a13+a19);
  if (res[7]!=0) res[7][0]=a13;
  a08=(a08*a30);
  a08=(a08/a31);
  a08=(a08*a26);
  a29=(a29?a08:0);
  a29=(a29+a22);
  a12=(a12*a29);
  a14=casadi_sq(a14);
  a28=(a28*a14);
  a28=(a28/a25);
  a28=(a28*a22);
  a28=(a28*a00);
  a12=(a12+a28);
  if (res[7]!=0) res[7][1]=a12;
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

CASADI_SYMBOL_EXPORT casadi_int contact_n_out(void) { return 8;}

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
    case 7: return "dissipation";
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
    case 7: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int contact_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 8;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int contact_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 8*sizeof(casadi_real*);
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
  a17=0.;
  a13=arg[1]? arg[1][21] : 0;
  a04=-9.9999999999999995e-07;
  a23=(a04*a13);
  a24=9.9999999999999995e-07;
  a28=arg[1]? arg[1][20] : 0;
  a02=(a24*a28);
  a23=(a23+a02);
  a23=casadi_sq(a23);
  a27=casadi_sq(a27);
  a07=casadi_sq(a07);
  a27=(a27+a07);
  a23=casadi_fmax(a23,a27);
  a23=sqrt(a23);
  a23=(a13+a23);
  a23=(a23-a28);
  a27=(a17<a23);
  a07=1.3333333333333333e+00;
  a02=(a28*a13);
  a28=(a28-a13);
  a02=(a02/a28);
  a02=sqrt(a02);
  a02=(a07*a02);
  a28=1.;
  a13=arg[1]? arg[1][33] : 0;
  a13=(a28+a13);
  a02=(a02/a13);
  a14=arg[1]? arg[1][23] : 0;
  a14=casadi_sq(a14);
  a14=(a28-a14);
  a22=arg[1]? arg[1][22] : 0;
  a14=(a14/a22);
  a22=arg[1]? arg[1][25] : 0;
  a22=casadi_sq(a22);
  a22=(a28-a22);
  a19=arg[1]? arg[1][24] : 0;
  a22=(a22/a19);
  a14=(a14+a22);
  a02=(a02/a14);
  a14=1.0000000000000000e-300;
  a23=casadi_fmax(a14,a23);
  a23=pow(a23,a13);
  a02=(a02*a23);
  a27=(a27?a02:0);
  a02=arg[1]? arg[1][27] : 0;
  a04=(a04*a02);
  a23=arg[1]? arg[1][26] : 0;
  a24=(a24*a23);
  a04=(a04+a24);
  a04=casadi_sq(a04);
  a15=casadi_sq(a15);
  a16=casadi_sq(a16);
  a15=(a15+a16);
  a04=casadi_fmax(a04,a15);
  a04=sqrt(a04);
  a04=(a02+a04);
  a04=(a04-a23);
  a17=(a17<a04);
  a15=(a23*a02);
  a23=(a23-a02);
  a15=(a15/a23);
  a15=sqrt(a15);
  a07=(a07*a15);
  a07=(a07/a13);
  a15=arg[1]? arg[1][29] : 0;
  a15=casadi_sq(a15);
  a15=(a28-a15);
  a23=arg[1]? arg[1][28] : 0;
  a15=(a15/a23);
  a23=arg[1]? arg[1][31] : 0;
  a23=casadi_sq(a23);
  a28=(a28-a23);
  a23=arg[1]? arg[1][30] : 0;
  a28=(a28/a23);
  a15=(a15+a28);
  a07=(a07/a15);
  a14=casadi_fmax(a14,a04);
  a14=pow(a14,a13);
  a07=(a07*a14);
  a17=(a17?a07:0);
  a27=(a27+a17);
  if (res[2]!=0) res[2][0]=a27;
  a01=(a01-a00);
  a01=(a01+a27);
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

/* rk4_step:(x[12],tau_stages[2x3],h,p[39],v_imp[2])->(x_next[12]) */
static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i;
  casadi_real **res1=res+1, *rr, *w00=w+154, w01, w02, *w03=w+166, *w04=w+172, *w06=w+174, *w07=w+176, w08, *w09=w+188, *w10=w+200;
  const casadi_real **arg1=arg+5, *cr, *cs, *wr00, *wr05;
  wr00 = arg[0] ? arg[0] : casadi_zeros;
  w01 = arg[2] ? arg[2][0] : 0;
  w02 = 6.;
  w02  = (w01/w02);
  casadi_copy(arg[1], 6, w03);
  for (rr=w04, cs=w03+0; cs!=w03+2; cs+=1) *rr++ = *cs;
  wr05 = arg[3] ? arg[3] : casadi_zeros;
  casadi_copy(arg[4], 2, w06);
  arg1[0]=wr00;
  arg1[1]=w04;
  arg1[2]=wr05;
  arg1[3]=w06;
  res1[0]=w07;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  w08 = 2.;
  w08  = (w01/w08);
  for (i=0, rr=w09, cs=w07; i<12; ++i) (*rr++)  = (w08*(*cs++));
  for (i=0, rr=w09, cr=wr00, cs=w09; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w04, cs=w03+2; cs!=w03+4; cs+=1) *rr++ = *cs;
  arg1[0]=w09;
  arg1[1]=w04;
  arg1[2]=wr05;
  arg1[3]=w06;
  res1[0]=w10;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (i=0, rr=w09, cs=w10; i<12; ++i) *rr++ = (2.* *cs++ );
  for (i=0, rr=w07, cs=w09; i<12; ++i) (*rr++) += (*cs++);
  w08 = 2.;
  w08  = (w01/w08);
  for (i=0, rr=w10, cs=w10; i<12; ++i) (*rr++)  = (w08*(*cs++));
  for (i=0, rr=w10, cr=wr00, cs=w10; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w04, cs=w03+2; cs!=w03+4; cs+=1) *rr++ = *cs;
  arg1[0]=w10;
  arg1[1]=w04;
  arg1[2]=wr05;
  arg1[3]=w06;
  res1[0]=w09;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (i=0, rr=w10, cs=w09; i<12; ++i) *rr++ = (2.* *cs++ );
  for (i=0, rr=w07, cs=w10; i<12; ++i) (*rr++) += (*cs++);
  for (i=0, rr=w09, cs=w09; i<12; ++i) (*rr++)  = (w01*(*cs++));
  for (i=0, rr=w09, cr=wr00, cs=w09; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w04, cs=w03+4; cs!=w03+6; cs+=1) *rr++ = *cs;
  arg1[0]=w09;
  arg1[1]=w04;
  arg1[2]=wr05;
  arg1[3]=w06;
  res1[0]=w10;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (i=0, rr=w07, cs=w10; i<12; ++i) (*rr++) += (*cs++);
  for (i=0, rr=w07, cs=w07; i<12; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w00, cr=wr00, cs=w07; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  casadi_copy(w00, 12, res[0]);
  return 0;
}

CASADI_SYMBOL_EXPORT int rk4_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f8(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int rk4_step_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void rk4_step_release(int mem) {
}

CASADI_SYMBOL_EXPORT void rk4_step_incref(void) {
}

CASADI_SYMBOL_EXPORT void rk4_step_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int rk4_step_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int rk4_step_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real rk4_step_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* rk4_step_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau_stages";
    case 2: return "h";
    case 3: return "p";
    case 4: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* rk4_step_name_out(casadi_int i) {
  switch (i) {
    case 0: return "x_next";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* rk4_step_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s20;
    case 2: return casadi_s19;
    case 3: return casadi_s1;
    case 4: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* rk4_step_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int rk4_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 212;
  return 0;
}

CASADI_SYMBOL_EXPORT int rk4_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 212*sizeof(casadi_real);
  return 0;
}

/* radau_step:(x[12],tau_stages[2x3],h,p[39],v_imp[2])->(x_next[12],newton_increment) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i;
  casadi_real *qr_beta, *qr_r, *qr_v, *qr_w, **res1=res+2, *rr, *w00=w+1403, *w01=w+1415, *w02=w+1451, *w03=w+2747, *w04=w+2783, w05;
  casadi_real *w07=w+3503, *w08=w+3509, *w10=w+3511, *w12=w+3513, *w13=w+3591, *w14=w+4293, *w15=w+5013, *w16=w+5025, *w17=w+5037, *w18=w+5049, *w19=w+5085, *w20=w+5097;
  const casadi_real **arg1=arg+5, *cr, *cs, *ss, *wr00, *wr02, *wr06, *wr09;
  wr00 = arg[0] ? arg[0] : casadi_zeros;
  casadi_clear(w01, 36);
  wr02 = casadi_c0;
  casadi_fill(w03, 36, 1.);
  casadi_project(w03, casadi_s21, w04, casadi_s22, w);
  w05 = arg[2] ? arg[2][0] : 0;
  wr06 = casadi_c1;
  casadi_copy(arg[1], 6, w07);
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  wr09 = arg[3] ? arg[3] : casadi_zeros;
  casadi_copy(arg[4], 2, w10);
  arg1[0]=wr00;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  arg1[4]=0;
  res1[0]=w12;
  res1[1]=0;
  res1[2]=0;
  res1[3]=0;
  if (casadi_f3(arg1, res1, iw, w, 0)) return 1;
  casadi_kron_dense_sparse(wr06, 3, 3, w12, casadi_s9, w13);
  for (i=0, rr=w13, cs=w13; i<702; ++i) (*rr++)  = (w05*(*cs++));
  casadi_project(w13, casadi_s23, w14, casadi_s22, w);
  for (i=0, rr=w04, cs=w14; i<720; ++i) (*rr++) -= (*cs++);
  rr = w02;
  ss = w04;
  casadi_copy(wr02, 1296, rr);
  qr_v = w;
  qr_r = w+549;
  qr_beta = w+1215;
  qr_w = w+1251;
  casadi_qr(casadi_s22, ss, qr_w, casadi_s26, qr_v, casadi_s27, qr_r, qr_beta, casadi_s24, casadi_s25);
  casadi_qr_solve(rr, 36, 0, casadi_s26, qr_v, casadi_s27, qr_r, qr_beta, casadi_s24, casadi_s25, qr_w);
  casadi_clear(w03, 36);
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w15;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w16;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w18;
  for (i=0, cs=w15; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w16; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w18, 12, 3, wr06, 3, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  casadi_mtimes_dense(w02, 36, 36, w03, 1, w01, 0);
  for (i=0, rr=w01, cs=w01; i<36; ++i) *rr++ = (- *cs++ );
  casadi_clear(w03, 36);
  casadi_clear(w18, 36);
  for (rr=w15, cs=w01+0; cs!=w01+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w15, cr=wr00, cs=w15; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=w15;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w16;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w15, cs=w01+12; cs!=w01+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w15, cr=wr00, cs=w15; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=w15;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w15, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w15, cr=wr00, cs=w15; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=w15;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w20;
  for (i=0, cs=w16; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w20, 12, 3, wr06, 3, w18, 0);
  for (i=0, rr=w18, cs=w18; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w18, cr=w01, cs=w18; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  casadi_mtimes_dense(w02, 36, 36, w18, 1, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w01, cs=w03; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w03, 36);
  casadi_clear(w18, 36);
  for (rr=w16, cs=w01+0; cs!=w01+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w16, cr=wr00, cs=w16; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=w16;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w16, cs=w01+12; cs!=w01+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w16, cr=wr00, cs=w16; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=w16;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w16, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w16, cr=wr00, cs=w16; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=w16;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w15;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w20;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w15; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w20, 12, 3, wr06, 3, w18, 0);
  for (i=0, rr=w18, cs=w18; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w18, cr=w01, cs=w18; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  casadi_mtimes_dense(w02, 36, 36, w18, 1, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w01, cs=w03; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w03, 36);
  casadi_clear(w18, 36);
  for (rr=w17, cs=w01+0; cs!=w01+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=w17;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w01+12; cs!=w01+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=w17;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w15;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=w17;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w16;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w20;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w15; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w16; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w20, 12, 3, wr06, 3, w18, 0);
  for (i=0, rr=w18, cs=w18; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w18, cr=w01, cs=w18; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  casadi_mtimes_dense(w02, 36, 36, w18, 1, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w01, cs=w03; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w03, 36);
  casadi_clear(w18, 36);
  for (rr=w19, cs=w01+0; cs!=w01+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w15;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w01+12; cs!=w01+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w16;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w20;
  for (i=0, cs=w15; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w16; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w20, 12, 3, wr06, 3, w18, 0);
  for (i=0, rr=w18, cs=w18; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w18, cr=w01, cs=w18; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  casadi_mtimes_dense(w02, 36, 36, w18, 1, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w01, cs=w03; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w03, 36);
  casadi_clear(w18, 36);
  for (rr=w15, cs=w01+0; cs!=w01+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w15, cr=wr00, cs=w15; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=w15;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w16;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w15, cs=w01+12; cs!=w01+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w15, cr=wr00, cs=w15; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=w15;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w15, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w15, cr=wr00, cs=w15; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=w15;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w20;
  for (i=0, cs=w16; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w20, 12, 3, wr06, 3, w18, 0);
  for (i=0, rr=w18, cs=w18; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w18, cr=w01, cs=w18; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  casadi_mtimes_dense(w02, 36, 36, w18, 1, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w01, cs=w03; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w03, 36);
  casadi_clear(w18, 36);
  for (rr=w16, cs=w01+0; cs!=w01+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w16, cr=wr00, cs=w16; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=w16;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w16, cs=w01+12; cs!=w01+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w16, cr=wr00, cs=w16; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=w16;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w16, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w16, cr=wr00, cs=w16; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=w16;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w15;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w20;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w15; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w20, 12, 3, wr06, 3, w18, 0);
  for (i=0, rr=w18, cs=w18; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w18, cr=w01, cs=w18; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  casadi_mtimes_dense(w02, 36, 36, w18, 1, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w01, cs=w03; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w03, 36);
  casadi_clear(w18, 36);
  for (rr=w17, cs=w01+0; cs!=w01+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+0; cs!=w07+2; cs+=1) *rr++ = *cs;
  arg1[0]=w17;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w01+12; cs!=w01+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+2; cs!=w07+4; cs+=1) *rr++ = *cs;
  arg1[0]=w17;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w15;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w08, cs=w07+4; cs!=w07+6; cs+=1) *rr++ = *cs;
  arg1[0]=w17;
  arg1[1]=w08;
  arg1[2]=wr09;
  arg1[3]=w10;
  res1[0]=w16;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w20;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w15; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w16; i<12; ++i) *rr++ = *cs++;
  wr06 = casadi_c2;
  casadi_mtimes_dense(w20, 12, 3, wr06, 3, w18, 0);
  for (i=0, rr=w18, cs=w18; i<36; ++i) (*rr++)  = (w05*(*cs++));
  for (i=0, rr=w18, cr=w01, cs=w18; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  casadi_mtimes_dense(w02, 36, 36, w18, 1, w03, 0);
  for (i=0, rr=w03, cs=w03; i<36; ++i) *rr++ = (- *cs++ );
  casadi_copy(w03, 36, w18);
  for (i=0, rr=w01, cs=w18; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w19, cs=w01+24; cs!=w01+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w00, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  casadi_copy(w00, 12, res[0]);
  w05 = casadi_norm_inf(36, w03);
  if (res[1]) res[1][0] = w05;
  return 0;
}

CASADI_SYMBOL_EXPORT int radau_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f9(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int radau_step_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void radau_step_release(int mem) {
}

CASADI_SYMBOL_EXPORT void radau_step_incref(void) {
}

CASADI_SYMBOL_EXPORT void radau_step_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int radau_step_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int radau_step_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real radau_step_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* radau_step_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau_stages";
    case 2: return "h";
    case 3: return "p";
    case 4: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* radau_step_name_out(casadi_int i) {
  switch (i) {
    case 0: return "x_next";
    case 1: return "newton_increment";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* radau_step_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s20;
    case 2: return casadi_s19;
    case 3: return casadi_s1;
    case 4: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* radau_step_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s19;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int radau_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15;
  if (sz_res) *sz_res = 10;
  if (sz_iw) *sz_iw = 40;
  if (sz_w) *sz_w = 5133;
  return 0;
}

CASADI_SYMBOL_EXPORT int radau_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 10*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 40*sizeof(casadi_int);
  if (sz_w) *sz_w = 5133*sizeof(casadi_real);
  return 0;
}


