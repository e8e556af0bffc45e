/* GENERATED FILE: DO NOT EDIT.
 * Regenerate: `jointplay derive robot.toml --out <this folder>`, or for the models
 * checked in under generated/: `pytest tests/test_generated.py --update-generated`.
 * model: paper_4dof
 * generator: jointplay.derive 0.1.0+a6801daa8664, casadi 3.8.2, sympy 1.14.0
 * formulation: closed
 * input hash: 00feb04a41f513cd759af3db823a67b1558bd90ec6168ffd56a0a4c8f0e4dc4c
 * Every input and output slot is described, with names and units, in layout.json.
 * Functions (inputs -> outputs; column vectors, dense, float64):
 *   mass_matrix(q[6], p[39]) -> M[6x6]
 *   forcing(x[12], tau[2], p[39], v_imp[2]) -> f[6x1]
 *   forward_dynamics(x[12], tau[2], p[39], v_imp[2]) -> xdot[12x1]
 *   jac_forward_dynamics: d forward_dynamics / d each input, CasADi's calling convention
 *   jac_state(x[12], tau[2], p[39], v_imp[2]) -> jac_xdot_x[12x12]
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
#define casadi_c3 CASADI_PREFIX(c3)
#define casadi_clear CASADI_PREFIX(clear)
#define casadi_copy CASADI_PREFIX(copy)
#define casadi_densify CASADI_PREFIX(densify)
#define casadi_dot CASADI_PREFIX(dot)
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_f1 CASADI_PREFIX(f1)
#define casadi_f10 CASADI_PREFIX(f10)
#define casadi_f11 CASADI_PREFIX(f11)
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
#define casadi_kron_dense CASADI_PREFIX(kron_dense)
#define casadi_kron_dense_sparse CASADI_PREFIX(kron_dense_sparse)
#define casadi_ldl CASADI_PREFIX(ldl)
#define casadi_ldl_solve CASADI_PREFIX(ldl_solve)
#define casadi_ldl_trs CASADI_PREFIX(ldl_trs)
#define casadi_mtimes CASADI_PREFIX(mtimes)
#define casadi_mtimes_dense CASADI_PREFIX(mtimes_dense)
#define casadi_norm_inf CASADI_PREFIX(norm_inf)
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

void casadi_kron_dense(const casadi_real* a, casadi_int mA, casadi_int nA,
                       const casadi_real* b, casadi_int mB, casadi_int nB,
                       casadi_real* r) {
    casadi_int j, s, i, rr, k;
    casadi_real a_val;
    k = 0;
    for (j=0; j<nA; ++j) {
      for (s=0; s<nB; ++s) {
        for (i=0; i<mA; ++i) {
          a_val = a[j*mA + i];
          for (rr=0; rr<mB; ++rr) {
            r[k++] = a_val * b[s*mB + rr];
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

void casadi_mtimes(const casadi_real* x, const casadi_int* sp_x, const casadi_real* y, const casadi_int* sp_y, casadi_real* z, const casadi_int* sp_z, casadi_real* w, casadi_int tr) {
  casadi_int ncol_x, ncol_y, ncol_z, cc;
  const casadi_int *colind_x, *row_x, *colind_y, *row_y, *colind_z, *row_z;
  ncol_x = sp_x[1];
  colind_x = sp_x+2; row_x = sp_x + 2 + ncol_x+1;
  ncol_y = sp_y[1];
  colind_y = sp_y+2; row_y = sp_y + 2 + ncol_y+1;
  ncol_z = sp_z[1];
  colind_z = sp_z+2; row_z = sp_z + 2 + ncol_z+1;
  if (tr) {
    for (cc=0; cc<ncol_z; ++cc) {
      casadi_int kk;
      for (kk=colind_y[cc]; kk<colind_y[cc+1]; ++kk) {
        w[row_y[kk]] = y[kk];
      }
      for (kk=colind_z[cc]; kk<colind_z[cc+1]; ++kk) {
        casadi_int kk1;
        casadi_int rr = row_z[kk];
        for (kk1=colind_x[rr]; kk1<colind_x[rr+1]; ++kk1) {
          z[kk] += x[kk1] * w[row_x[kk1]];
        }
      }
    }
  } else {
    for (cc=0; cc<ncol_y; ++cc) {
      casadi_int kk;
      for (kk=colind_z[cc]; kk<colind_z[cc+1]; ++kk) {
        w[row_z[kk]] = z[kk];
      }
      for (kk=colind_y[cc]; kk<colind_y[cc+1]; ++kk) {
        casadi_int kk1;
        casadi_int rr = row_y[kk];
        for (kk1=colind_x[rr]; kk1<colind_x[rr+1]; ++kk1) {
          w[row_x[kk1]] += x[kk1]*y[kk];
        }
      }
      for (kk=colind_z[cc]; kk<colind_z[cc+1]; ++kk) {
        z[kk] = w[row_z[kk]];
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
static const casadi_int casadi_s21[15] = 
  {6, 6, 0, 1, 2, 3, 4, 5,
  6, 0, 1, 2, 3, 4, 5};
static const casadi_int casadi_s22[18] = 
  {0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 15,
  16, 17};
static const casadi_int casadi_s23[345] = 
  {18, 18, 0, 18, 36, 54, 72, 90,
  108, 126, 144, 162, 180, 198, 216, 234,
  252, 270, 288, 306, 324, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17};
static const casadi_int casadi_s24[192] = 
  {18, 18, 0, 18, 35, 51, 66, 80,
  93, 105, 116, 126, 135, 143, 150, 156,
  161, 165, 168, 170, 171, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 1,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 11, 12, 13, 14, 15, 16, 17,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 11, 12, 13, 14, 15, 16, 17,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 17, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  13, 14, 15, 16, 17, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 15,
  16, 17, 6, 7, 8, 9, 10, 11,
  12, 13, 14, 15, 16, 17, 7, 8,
  9, 10, 11, 12, 13, 14, 15, 16,
  17, 8, 9, 10, 11, 12, 13, 14,
  15, 16, 17, 9, 10, 11, 12, 13,
  14, 15, 16, 17, 10, 11, 12, 13,
  14, 15, 16, 17, 11, 12, 13, 14,
  15, 16, 17, 12, 13, 14, 15, 16,
  17, 13, 14, 15, 16, 17, 14, 15,
  16, 17, 15, 16, 17, 16, 17, 17};
static const casadi_int casadi_s25[192] = 
  {18, 18, 0, 1, 3, 6, 10, 15,
  21, 28, 36, 45, 55, 66, 78, 91,
  105, 120, 136, 153, 171, 0, 0, 1,
  0, 1, 2, 0, 1, 2, 3, 0,
  1, 2, 3, 4, 0, 1, 2, 3,
  4, 5, 0, 1, 2, 3, 4, 5,
  6, 0, 1, 2, 3, 4, 5, 6,
  7, 0, 1, 2, 3, 4, 5, 6,
  7, 8, 0, 1, 2, 3, 4, 5,
  6, 7, 8, 9, 0, 1, 2, 3,
  4, 5, 6, 7, 8, 9, 10, 0,
  1, 2, 3, 4, 5, 6, 7, 8,
  9, 10, 11, 0, 1, 2, 3, 4,
  5, 6, 7, 8, 9, 10, 11, 12,
  0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 0, 1,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 11, 12, 13, 14, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 0, 1, 2,
  3, 4, 5, 6, 7, 8, 9, 10,
  11, 12, 13, 14, 15, 16, 0, 1,
  2, 3, 4, 5, 6, 7, 8, 9,
  10, 11, 12, 13, 14, 15, 16, 17};
static const casadi_int casadi_s26[22] = 
  {18, 1, 0, 18, 0, 1, 2, 3,
  4, 5, 6, 7, 8, 9, 10, 11,
  12, 13, 14, 15, 16, 17};
static const casadi_int casadi_s27[75] = 
  {18, 18, 0, 3, 6, 9, 12, 15,
  18, 21, 24, 27, 30, 33, 36, 39,
  42, 45, 48, 51, 54, 0, 6, 12,
  1, 7, 13, 2, 8, 14, 3, 9,
  15, 4, 10, 16, 5, 11, 17, 0,
  6, 12, 1, 7, 13, 2, 8, 14,
  3, 9, 15, 4, 10, 16, 5, 11,
  17, 0, 6, 12, 1, 7, 13, 2,
  8, 14, 3, 9, 15, 4, 10, 16,
  5, 11, 17};

static const casadi_real casadi_c0[9] = 
  {1.9681547722366044e-01, 3.9442431473908729e-01, 3.7640306270046725e-01, -6.5535425850198378e-02, 2.9207341166522843e-01, 5.1248582618842164e-01, 2.3770974348220151e-02, -4.1548752125997922e-02,
  1.1111111111111110e-01};
static const casadi_real casadi_c1[324] = 
  {1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 1., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 1., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 1., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 1., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 1.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 1., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 1., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 1., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 1., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 1., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 1., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 1.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 1., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 1., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  1., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 0., 0., 0., 0., 0.,
  0., 0., 0., 1.};
static const casadi_real casadi_c2[9] = 
  {2.1835034190722750e-02, 1.7719058743194560e-01, 3.1804138174397717e-01, -1.9857254098612269e-02, 3.8164965809277238e-02, 1.8195861825602283e-01, 1.0042630196562409e-02, -7.3759635298957385e-03,
  0.};
static const casadi_real casadi_c3[9] = 
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

/* residual_jacobian:(i0[12],i1[6],i2[2],i3[39],i4[2])->(o0[6x12,52nz]) */
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
  casadi_real a108, a109, a110, a111, a112;
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
  a005=sin(a005);
  a024=(a002*a005);
  a009=sin(a009);
  a025=(a008*a009);
  a025=(a024+a025);
  a026=(a023*a025);
  a018=(a018-a026);
  a018=(a001*a018);
  a026=arg[3]? arg[3][13] : 0;
  a027=arg[3]? arg[3][8] : 0;
  a028=(a027*a011);
  a029=(a007+a028);
  a030=arg[3]? arg[3][15] : 0;
  a031=arg[3]? arg[3][32] : 0;
  a003=(a003+a031);
  a003=(a003+a004);
  a003=(a003+a010);
  a010=sin(a003);
  a004=(a030*a010);
  a029=(a029+a004);
  a031=(2.*a029);
  a032=(a027*a016);
  a033=(a015+a032);
  a034=cos(a003);
  a035=(a030*a034);
  a033=(a033+a035);
  a036=(a031*a033);
  a037=(a027*a021);
  a038=(a020+a037);
  a039=cos(a003);
  a040=(a030*a039);
  a038=(a038+a040);
  a041=(2.*a038);
  a042=(a027*a009);
  a043=(a024+a042);
  a003=sin(a003);
  a044=(a030*a003);
  a043=(a043+a044);
  a045=(a041*a043);
  a036=(a036-a045);
  a036=(a026*a036);
  a018=(a018+a036);
  a036=arg[3]? arg[3][16] : 0;
  a007=(a007+a028);
  a045=arg[3]? arg[3][12] : 0;
  a046=(a045*a010);
  a007=(a007+a046);
  a047=(2.*a007);
  a015=(a015+a032);
  a048=(a045*a034);
  a015=(a015+a048);
  a049=(a047*a015);
  a020=(a020+a037);
  a050=(a045*a039);
  a020=(a020+a050);
  a051=(2.*a020);
  a024=(a024+a042);
  a052=(a045*a003);
  a024=(a024+a052);
  a053=(a051*a024);
  a049=(a049-a053);
  a049=(a036*a049);
  a018=(a018+a049);
  a018=(a000*a018);
  a049=arg[1]? arg[1][1] : 0;
  a053=(a008*a017);
  a053=(a011*a053);
  a054=(a008*a012);
  a055=(a054*a016);
  a053=(a053+a055);
  a055=(a008*a025);
  a055=(a021*a055);
  a056=(a008*a022);
  a057=(a056*a009);
  a055=(a055+a057);
  a053=(a053-a055);
  a053=(a001*a053);
  a035=(a032+a035);
  a055=(a029*a035);
  a004=(a028+a004);
  a057=(a004*a033);
  a055=(a055+a057);
  a044=(a042+a044);
  a057=(a038*a044);
  a040=(a037+a040);
  a058=(a040*a043);
  a057=(a057+a058);
  a055=(a055-a057);
  a055=(a026*a055);
  a053=(a053+a055);
  a032=(a032+a048);
  a048=(a007*a032);
  a028=(a028+a046);
  a046=(a028*a015);
  a048=(a048+a046);
  a042=(a042+a052);
  a052=(a020*a042);
  a037=(a037+a050);
  a050=(a037*a024);
  a052=(a052+a050);
  a048=(a048-a052);
  a048=(a036*a048);
  a053=(a053+a048);
  a048=(a049*a053);
  a018=(a018+a048);
  a048=arg[1]? arg[1][2] : 0;
  a052=(a001*a017);
  a050=(a026*a033);
  a046=(a052+a050);
  a055=(a036*a015);
  a046=(a046+a055);
  a057=arg[3]? arg[3][7] : 0;
  a058=arg[3]? arg[3][5] : 0;
  a059=(a057*a058);
  a059=(a059*a014);
  a046=(a046+a059);
  a059=(a048*a046);
  a018=(a018-a059);
  a059=arg[1]? arg[1][3] : 0;
  a060=(a001*a025);
  a061=(a026*a043);
  a062=(a060+a061);
  a063=(a036*a024);
  a062=(a062+a063);
  a064=(a057*a058);
  a064=(a064*a005);
  a062=(a062+a064);
  a064=(a059*a062);
  a018=(a018-a064);
  a064=arg[1]? arg[1][4] : 0;
  a052=(a052+a050);
  a052=(a052+a055);
  a055=(a064*a052);
  a018=(a018-a055);
  a055=arg[1]? arg[1][5] : 0;
  a060=(a060+a061);
  a060=(a060+a063);
  a063=(a055*a060);
  a018=(a018-a063);
  a022=(a001*a022);
  a063=arg[0]? arg[0][6] : 0;
  a061=casadi_sq(a063);
  a050=(a002*a061);
  a065=(a050*a014);
  a066=arg[0]? arg[0][7] : 0;
  a066=(a063+a066);
  a067=casadi_sq(a066);
  a068=(a008*a067);
  a069=(a068*a016);
  a069=(a065+a069);
  a070=(a022*a069);
  a050=(a050*a006);
  a071=(a068*a011);
  a071=(a050+a071);
  a072=(a001*a025);
  a072=(a071*a072);
  a070=(a070-a072);
  a072=arg[3]? arg[3][17] : 0;
  a073=(a072*a001);
  a074=(a073*a017);
  a075=(a072*a026);
  a076=(a075*a033);
  a074=(a074+a076);
  a076=(a072*a036);
  a077=(a076*a015);
  a074=(a074+a077);
  a077=arg[3]? arg[3][18] : 0;
  a078=(a077*a001);
  a025=(a078*a025);
  a074=(a074+a025);
  a025=(a077*a026);
  a079=(a025*a043);
  a074=(a074+a079);
  a079=(a077*a036);
  a080=(a079*a024);
  a074=(a074+a080);
  a070=(a070-a074);
  a074=(a002*a061);
  a080=(a074*a019);
  a081=(a008*a067);
  a082=(a081*a021);
  a082=(a080+a082);
  a017=(a001*a017);
  a017=(a082*a017);
  a012=(a001*a012);
  a074=(a074*a005);
  a083=(a081*a009);
  a083=(a074+a083);
  a084=(a012*a083);
  a017=(a017-a084);
  a070=(a070-a017);
  a017=(a026*a038);
  a084=(a027*a067);
  a085=(a084*a016);
  a086=(a065+a085);
  a087=(a030*a067);
  a088=(a087*a034);
  a086=(a086+a088);
  a088=(a017*a086);
  a089=(a084*a011);
  a090=(a050+a089);
  a091=(a087*a010);
  a090=(a090+a091);
  a043=(a026*a043);
  a043=(a090*a043);
  a088=(a088-a043);
  a070=(a070+a088);
  a088=(a027*a067);
  a043=(a088*a021);
  a091=(a080+a043);
  a092=(a030*a067);
  a093=(a092*a039);
  a091=(a091+a093);
  a033=(a026*a033);
  a033=(a091*a033);
  a093=(a026*a029);
  a094=(a088*a009);
  a095=(a074+a094);
  a096=(a092*a003);
  a095=(a095+a096);
  a096=(a093*a095);
  a033=(a033-a096);
  a070=(a070-a033);
  a033=(a036*a020);
  a065=(a065+a085);
  a085=(a045*a067);
  a096=(a085*a034);
  a065=(a065+a096);
  a096=(a033*a065);
  a050=(a050+a089);
  a089=(a085*a010);
  a050=(a050+a089);
  a024=(a036*a024);
  a024=(a050*a024);
  a096=(a096-a024);
  a070=(a070+a096);
  a080=(a080+a043);
  a067=(a045*a067);
  a043=(a067*a039);
  a080=(a080+a043);
  a015=(a036*a015);
  a015=(a080*a015);
  a043=(a036*a007);
  a074=(a074+a094);
  a094=(a067*a003);
  a074=(a074+a094);
  a094=(a043*a074);
  a015=(a015-a094);
  a070=(a070-a015);
  a015=(a057*a077);
  a015=(a015*a058);
  a015=(a015*a005);
  a070=(a070-a015);
  a015=(a057*a072);
  a015=(a015*a058);
  a015=(a015*a014);
  a070=(a070-a015);
  a018=(a018-a070);
  if (res[0]!=0) res[0][0]=a018;
  a053=(a000*a053);
  a018=(2.*a004);
  a070=(a018*a035);
  a015=(2.*a040);
  a094=(a015*a044);
  a070=(a070-a094);
  a070=(a026*a070);
  a094=(2.*a028);
  a096=(a094*a032);
  a024=(2.*a037);
  a089=(a024*a042);
  a096=(a096-a089);
  a096=(a036*a096);
  a070=(a070+a096);
  a070=(a049*a070);
  a053=(a053+a070);
  a070=(a026*a035);
  a096=(a036*a032);
  a070=(a070+a096);
  a096=(a008*a001);
  a089=(a096*a016);
  a070=(a070+a089);
  a089=(a048*a070);
  a053=(a053-a089);
  a089=(a026*a044);
  a097=(a036*a042);
  a089=(a089+a097);
  a097=(a008*a001);
  a098=(a097*a009);
  a089=(a089+a098);
  a098=(a059*a089);
  a053=(a053-a098);
  a098=(a064*a070);
  a053=(a053-a098);
  a098=(a055*a089);
  a053=(a053-a098);
  a098=(a026*a040);
  a099=(a098*a086);
  a100=(a026*a044);
  a100=(a090*a100);
  a099=(a099-a100);
  a100=(a072*a026);
  a101=(a100*a035);
  a102=(a072*a036);
  a103=(a102*a032);
  a101=(a101+a103);
  a103=(a077*a026);
  a044=(a103*a044);
  a101=(a101+a044);
  a044=(a077*a036);
  a104=(a044*a042);
  a101=(a101+a104);
  a099=(a099-a101);
  a035=(a026*a035);
  a035=(a091*a035);
  a101=(a026*a004);
  a104=(a101*a095);
  a035=(a035-a104);
  a099=(a099-a035);
  a035=(a036*a037);
  a104=(a035*a065);
  a042=(a036*a042);
  a042=(a050*a042);
  a104=(a104-a042);
  a099=(a099+a104);
  a032=(a036*a032);
  a032=(a080*a032);
  a104=(a036*a028);
  a042=(a104*a074);
  a032=(a032-a042);
  a099=(a099-a032);
  a077=(a008*a077);
  a077=(a077*a001);
  a032=(a077*a009);
  a099=(a099-a032);
  a032=(a008*a001);
  a042=(a032*a082);
  a105=(a042*a016);
  a106=(a032*a083);
  a106=(a011*a106);
  a105=(a105-a106);
  a099=(a099-a105);
  a072=(a008*a072);
  a072=(a072*a001);
  a105=(a072*a016);
  a099=(a099-a105);
  a105=(a008*a001);
  a106=(a105*a069);
  a106=(a021*a106);
  a107=(a105*a071);
  a108=(a107*a009);
  a106=(a106-a108);
  a099=(a099+a106);
  a053=(a053-a099);
  if (res[0]!=0) res[0][1]=a053;
  a083=(a001*a083);
  a095=(a026*a095);
  a053=(a083+a095);
  a074=(a036*a074);
  a053=(a053+a074);
  a099=(a057*a058);
  a106=(a099*a061);
  a106=(a106*a005);
  a053=(a053+a106);
  a046=(a000*a046);
  a106=(a049*a070);
  a046=(a046+a106);
  a053=(a053-a046);
  if (res[0]!=0) res[0][2]=a053;
  a062=(a000*a062);
  a053=(a049*a089);
  a062=(a062+a053);
  a069=(a001*a069);
  a086=(a026*a086);
  a053=(a069+a086);
  a065=(a036*a065);
  a053=(a053+a065);
  a057=(a057*a058);
  a061=(a057*a061);
  a061=(a061*a014);
  a053=(a053+a061);
  a062=(a062+a053);
  a062=(-a062);
  if (res[0]!=0) res[0][3]=a062;
  a083=(a083+a095);
  a083=(a083+a074);
  a052=(a000*a052);
  a070=(a049*a070);
  a052=(a052+a070);
  a083=(a083-a052);
  if (res[0]!=0) res[0][4]=a083;
  a060=(a000*a060);
  a089=(a049*a089);
  a060=(a060+a089);
  a069=(a069+a086);
  a069=(a069+a065);
  a060=(a060+a069);
  a060=(-a060);
  if (res[0]!=0) res[0][5]=a060;
  a060=(a008*a016);
  a013=(a013*a060);
  a069=(a008*a009);
  a023=(a023*a069);
  a013=(a013-a023);
  a013=(a001*a013);
  a023=(a027*a016);
  a065=(a030*a034);
  a086=(a023+a065);
  a031=(a031*a086);
  a089=(a027*a009);
  a083=(a030*a003);
  a052=(a089+a083);
  a041=(a041*a052);
  a031=(a031-a041);
  a031=(a026*a031);
  a013=(a013+a031);
  a031=(a045*a034);
  a041=(a023+a031);
  a047=(a047*a041);
  a070=(a045*a003);
  a074=(a089+a070);
  a051=(a051*a074);
  a047=(a047-a051);
  a047=(a036*a047);
  a013=(a013+a047);
  a013=(a000*a013);
  a047=(a008*a060);
  a047=(a011*a047);
  a054=(a054*a016);
  a047=(a047+a054);
  a054=(a008*a069);
  a054=(a021*a054);
  a056=(a056*a009);
  a054=(a054+a056);
  a047=(a047-a054);
  a047=(a001*a047);
  a065=(a023+a065);
  a029=(a029*a065);
  a004=(a004*a086);
  a029=(a029+a004);
  a083=(a089+a083);
  a038=(a038*a083);
  a040=(a040*a052);
  a038=(a038+a040);
  a029=(a029-a038);
  a029=(a026*a029);
  a047=(a047+a029);
  a023=(a023+a031);
  a007=(a007*a023);
  a028=(a028*a041);
  a007=(a007+a028);
  a089=(a089+a070);
  a020=(a020*a089);
  a037=(a037*a074);
  a020=(a020+a037);
  a007=(a007-a020);
  a007=(a036*a007);
  a047=(a047+a007);
  a007=(a049*a047);
  a013=(a013+a007);
  a007=(a001*a060);
  a020=(a026*a086);
  a037=(a007+a020);
  a070=(a036*a041);
  a037=(a037+a070);
  a028=(a048*a037);
  a013=(a013-a028);
  a028=(a001*a069);
  a031=(a026*a052);
  a029=(a028+a031);
  a038=(a036*a074);
  a029=(a029+a038);
  a040=(a059*a029);
  a013=(a013-a040);
  a007=(a007+a020);
  a007=(a007+a070);
  a070=(a064*a007);
  a013=(a013-a070);
  a028=(a028+a031);
  a028=(a028+a038);
  a038=(a055*a028);
  a013=(a013-a038);
  a068=(a068*a016);
  a038=(a022*a068);
  a031=(a001*a069);
  a071=(a071*a031);
  a038=(a038-a071);
  a073=(a073*a060);
  a075=(a075*a086);
  a073=(a073+a075);
  a076=(a076*a041);
  a073=(a073+a076);
  a078=(a078*a069);
  a073=(a073+a078);
  a025=(a025*a052);
  a073=(a073+a025);
  a079=(a079*a074);
  a073=(a073+a079);
  a038=(a038-a073);
  a060=(a001*a060);
  a082=(a082*a060);
  a081=(a081*a009);
  a060=(a012*a081);
  a082=(a082-a060);
  a038=(a038-a082);
  a084=(a084*a016);
  a087=(a087*a034);
  a087=(a084+a087);
  a082=(a017*a087);
  a052=(a026*a052);
  a052=(a090*a052);
  a082=(a082-a052);
  a038=(a038+a082);
  a086=(a026*a086);
  a086=(a091*a086);
  a088=(a088*a009);
  a092=(a092*a003);
  a092=(a088+a092);
  a082=(a093*a092);
  a086=(a086-a082);
  a038=(a038-a086);
  a085=(a085*a034);
  a084=(a084+a085);
  a085=(a033*a084);
  a074=(a036*a074);
  a074=(a050*a074);
  a085=(a085-a074);
  a038=(a038+a085);
  a041=(a036*a041);
  a041=(a080*a041);
  a067=(a067*a003);
  a088=(a088+a067);
  a067=(a043*a088);
  a041=(a041-a067);
  a038=(a038-a041);
  a013=(a013-a038);
  if (res[0]!=0) res[0][6]=a013;
  a047=(a000*a047);
  a018=(a018*a065);
  a015=(a015*a083);
  a018=(a018-a015);
  a018=(a026*a018);
  a094=(a094*a023);
  a024=(a024*a089);
  a094=(a094-a024);
  a094=(a036*a094);
  a018=(a018+a094);
  a018=(a049*a018);
  a047=(a047+a018);
  a018=(a026*a065);
  a094=(a036*a023);
  a018=(a018+a094);
  a096=(a096*a016);
  a018=(a018+a096);
  a048=(a048*a018);
  a047=(a047-a048);
  a048=(a026*a083);
  a096=(a036*a089);
  a048=(a048+a096);
  a097=(a097*a009);
  a048=(a048+a097);
  a059=(a059*a048);
  a047=(a047-a059);
  a064=(a064*a018);
  a047=(a047-a064);
  a055=(a055*a048);
  a047=(a047-a055);
  a055=(a098*a087);
  a064=(a026*a083);
  a090=(a090*a064);
  a055=(a055-a090);
  a100=(a100*a065);
  a102=(a102*a023);
  a100=(a100+a102);
  a103=(a103*a083);
  a100=(a100+a103);
  a044=(a044*a089);
  a100=(a100+a044);
  a055=(a055-a100);
  a065=(a026*a065);
  a091=(a091*a065);
  a065=(a101*a092);
  a091=(a091-a065);
  a055=(a055-a091);
  a091=(a035*a084);
  a089=(a036*a089);
  a050=(a050*a089);
  a091=(a091-a050);
  a055=(a055+a091);
  a023=(a036*a023);
  a080=(a080*a023);
  a023=(a104*a088);
  a080=(a080-a023);
  a055=(a055-a080);
  a077=(a077*a009);
  a055=(a055-a077);
  a042=(a042*a016);
  a077=(a032*a081);
  a077=(a011*a077);
  a042=(a042-a077);
  a055=(a055-a042);
  a072=(a072*a016);
  a055=(a055-a072);
  a072=(a105*a068);
  a072=(a021*a072);
  a107=(a107*a009);
  a072=(a072-a107);
  a055=(a055+a072);
  a047=(a047-a055);
  if (res[0]!=0) res[0][7]=a047;
  a081=(a001*a081);
  a092=(a026*a092);
  a047=(a081+a092);
  a088=(a036*a088);
  a047=(a047+a088);
  a037=(a000*a037);
  a055=(a049*a018);
  a037=(a037+a055);
  a047=(a047-a037);
  if (res[0]!=0) res[0][8]=a047;
  a029=(a000*a029);
  a047=(a049*a048);
  a029=(a029+a047);
  a068=(a001*a068);
  a087=(a026*a087);
  a047=(a068+a087);
  a084=(a036*a084);
  a047=(a047+a084);
  a029=(a029+a047);
  a029=(-a029);
  if (res[0]!=0) res[0][9]=a029;
  a081=(a081+a092);
  a081=(a081+a088);
  a007=(a000*a007);
  a018=(a049*a018);
  a007=(a007+a018);
  a081=(a081-a007);
  if (res[0]!=0) res[0][10]=a081;
  a000=(a000*a028);
  a049=(a049*a048);
  a000=(a000+a049);
  a068=(a068+a087);
  a068=(a068+a084);
  a000=(a000+a068);
  a000=(-a000);
  if (res[0]!=0) res[0][11]=a000;
  a000=arg[3]? arg[3][21] : 0;
  a068=1.;
  a084=0.;
  a087=(a000*a063);
  a049=-9.9999999999999995e-07;
  a048=(a049*a000);
  a028=9.9999999999999995e-07;
  a081=arg[3]? arg[3][20] : 0;
  a007=(a028*a081);
  a048=(a048+a007);
  a048=casadi_sq(a048);
  a007=arg[0]? arg[0][2] : 0;
  a018=casadi_sq(a007);
  a088=arg[0]? arg[0][3] : 0;
  a092=casadi_sq(a088);
  a018=(a018+a092);
  a092=casadi_fmax(a048,a018);
  a029=-5.0000000000000000e-01;
  a047=pow(a092,a029);
  a037=(a047*a007);
  a055=arg[0]? arg[0][9] : 0;
  a072=(a037*a055);
  a087=(a087+a072);
  a072=(a047*a088);
  a107=arg[0]? arg[0][8] : 0;
  a009=(a072*a107);
  a087=(a087-a009);
  a009=casadi_fabs(a087);
  a016=arg[3]? arg[3][37] : 0;
  a042=(a009-a016);
  a077=arg[3]? arg[3][38] : 0;
  a080=(a077-a016);
  a042=(a042/a080);
  a023=casadi_fmax(a084,a042);
  a091=casadi_fmin(a068,a023);
  a050=sqrt(a092);
  a089=(a000+a050);
  a089=(a089-a081);
  a065=(a084<a089);
  a100=1.3333333333333333e+00;
  a044=(a081*a000);
  a081=(a081-a000);
  a044=(a044/a081);
  a044=sqrt(a044);
  a044=(a100*a044);
  a081=arg[3]? arg[3][23] : 0;
  a081=casadi_sq(a081);
  a081=(a068-a081);
  a103=arg[3]? arg[3][22] : 0;
  a081=(a081/a103);
  a103=arg[3]? arg[3][25] : 0;
  a103=casadi_sq(a103);
  a103=(a068-a103);
  a083=arg[3]? arg[3][24] : 0;
  a103=(a103/a083);
  a081=(a081+a103);
  a044=(a044/a081);
  a081=7.5000000000000000e-01;
  a103=-7.5000000000000000e-01;
  a083=arg[3]? arg[3][34] : 0;
  a083=casadi_sq(a083);
  a103=(a103*a083);
  a081=(a081+a103);
  a103=arg[4]? arg[4][0] : 0;
  a083=arg[3]? arg[3][35] : 0;
  a103=casadi_fmax(a103,a083);
  a103=(a081/a103);
  a102=(a047*a007);
  a090=(a102*a107);
  a064=(a047*a088);
  a059=(a064*a055);
  a090=(a090+a059);
  a090=(a103*a090);
  a090=(a068+a090);
  a090=(a044*a090);
  a059=1.0000000000000000e-300;
  a097=casadi_fmax(a059,a089);
  a096=arg[3]? arg[3][33] : 0;
  a094=pow(a097,a096);
  a024=(a090*a094);
  a024=(a065?a024:0);
  a015=casadi_fmax(a084,a024);
  a013=arg[3]? arg[3][36] : 0;
  a038=1.0000000000000000e-03;
  a038=(a038*a077);
  a077=casadi_fmax(a016,a038);
  a041=casadi_fmax(a077,a009);
  a067=(a013/a041);
  a003=-1.5000000000000000e+00;
  a092=pow(a092,a003);
  a092=(a029*a092);
  a085=(a048<=a018);
  a018=(a018<=a048);
  a018=(a018+a085);
  a085=(a085/a018);
  a018=(2.*a007);
  a018=(a085*a018);
  a048=(a092*a018);
  a074=(a007*a048);
  a074=(a074+a047);
  a074=(a055*a074);
  a034=(a088*a048);
  a034=(a107*a034);
  a074=(a074-a034);
  a034=(a067*a074);
  a086=(a067/a041);
  a082=(a077<=a009);
  a009=(a009<=a077);
  a009=(a009+a082);
  a082=(a082/a009);
  a009=casadi_sign(a087);
  a077=(a009*a074);
  a052=(a082*a077);
  a060=(a086*a052);
  a060=(a087*a060);
  a034=(a034-a060);
  a034=(a015*a034);
  a060=(a067*a087);
  a073=(a084<=a024);
  a024=(a024<=a084);
  a024=(a024+a073);
  a073=(a073/a024);
  a024=(a007*a048);
  a024=(a024+a047);
  a024=(a107*a024);
  a079=(a088*a048);
  a079=(a055*a079);
  a024=(a024+a079);
  a024=(a103*a024);
  a024=(a044*a024);
  a024=(a094*a024);
  a079=(a096-a068);
  a097=pow(a097,a079);
  a097=(a096*a097);
  a079=(a059<=a089);
  a089=(a089<=a059);
  a089=(a089+a079);
  a079=(a079/a089);
  a050=(2.*a050);
  a018=(a018/a050);
  a018=(a079*a018);
  a018=(a097*a018);
  a018=(a090*a018);
  a024=(a024+a018);
  a024=(a073*a024);
  a018=(a060*a024);
  a018=(a065?a018:0);
  a034=(a034+a018);
  a034=(a091*a034);
  a018=(a060*a015);
  a089=(a023<=a068);
  a023=(a068<=a023);
  a023=(a023+a089);
  a089=(a089/a023);
  a023=(a084<=a042);
  a042=(a042<=a084);
  a042=(a042+a023);
  a023=(a023/a042);
  a077=(a077/a080);
  a077=(a023*a077);
  a077=(a089*a077);
  a042=(a018*a077);
  a034=(a034+a042);
  a034=(a000*a034);
  if (res[0]!=0) res[0][12]=a034;
  a034=(a013*a048);
  a034=(a034/a041);
  a042=(a013*a047);
  a042=(a042/a041);
  a025=(a042/a041);
  a078=(a025*a052);
  a034=(a034-a078);
  a034=(a087*a034);
  a078=(a042*a074);
  a034=(a034+a078);
  a034=(a015*a034);
  a078=(a042*a087);
  a069=(a078*a024);
  a069=(a065?a069:0);
  a034=(a034+a069);
  a034=(a091*a034);
  a069=(a078*a015);
  a076=(a069*a077);
  a034=(a034+a076);
  a034=(a088*a034);
  a076=(a015*a048);
  a075=(a047*a024);
  a075=(a065?a075:0);
  a076=(a076+a075);
  a076=(a007*a076);
  a075=(a047*a015);
  a076=(a076+a075);
  a034=(a034-a076);
  a034=(-a034);
  if (res[0]!=0) res[0][13]=a034;
  a034=(a015*a048);
  a076=(a047*a024);
  a076=(a065?a076:0);
  a034=(a034+a076);
  a034=(a088*a034);
  a048=(a013*a048);
  a048=(a048/a041);
  a076=(a013*a047);
  a076=(a076/a041);
  a075=(a076/a041);
  a052=(a075*a052);
  a048=(a048-a052);
  a048=(a087*a048);
  a074=(a076*a074);
  a048=(a048+a074);
  a048=(a015*a048);
  a074=(a076*a087);
  a024=(a074*a024);
  a024=(a065?a024:0);
  a048=(a048+a024);
  a048=(a091*a048);
  a024=(a074*a015);
  a077=(a024*a077);
  a048=(a048+a077);
  a048=(a007*a048);
  a077=(a024*a091);
  a048=(a048+a077);
  a034=(a034+a048);
  if (res[0]!=0) res[0][14]=a034;
  a034=(2.*a088);
  a085=(a085*a034);
  a092=(a092*a085);
  a034=(a007*a092);
  a034=(a055*a034);
  a048=(a088*a092);
  a048=(a048+a047);
  a048=(a107*a048);
  a034=(a034-a048);
  a048=(a067*a034);
  a077=(a009*a034);
  a052=(a082*a077);
  a071=(a086*a052);
  a071=(a087*a071);
  a048=(a048-a071);
  a048=(a015*a048);
  a071=(a007*a092);
  a107=(a107*a071);
  a071=(a088*a092);
  a071=(a071+a047);
  a055=(a055*a071);
  a107=(a107+a055);
  a107=(a103*a107);
  a107=(a044*a107);
  a107=(a094*a107);
  a085=(a085/a050);
  a079=(a079*a085);
  a097=(a097*a079);
  a090=(a090*a097);
  a107=(a107+a090);
  a107=(a073*a107);
  a090=(a060*a107);
  a090=(a065?a090:0);
  a048=(a048+a090);
  a048=(a091*a048);
  a077=(a077/a080);
  a077=(a023*a077);
  a077=(a089*a077);
  a090=(a018*a077);
  a048=(a048+a090);
  a048=(a000*a048);
  if (res[0]!=0) res[0][15]=a048;
  a048=(a013*a092);
  a048=(a048/a041);
  a090=(a025*a052);
  a048=(a048-a090);
  a048=(a087*a048);
  a090=(a042*a034);
  a048=(a048+a090);
  a048=(a015*a048);
  a090=(a078*a107);
  a090=(a065?a090:0);
  a048=(a048+a090);
  a048=(a091*a048);
  a090=(a069*a077);
  a048=(a048+a090);
  a048=(a088*a048);
  a090=(a069*a091);
  a048=(a048+a090);
  a090=(a015*a092);
  a097=(a047*a107);
  a097=(a065?a097:0);
  a090=(a090+a097);
  a090=(a007*a090);
  a048=(a048-a090);
  a048=(-a048);
  if (res[0]!=0) res[0][16]=a048;
  a048=(a015*a092);
  a090=(a047*a107);
  a090=(a065?a090:0);
  a048=(a048+a090);
  a048=(a088*a048);
  a090=(a047*a015);
  a048=(a048+a090);
  a092=(a013*a092);
  a092=(a092/a041);
  a052=(a075*a052);
  a092=(a092-a052);
  a092=(a087*a092);
  a034=(a076*a034);
  a092=(a092+a034);
  a092=(a015*a092);
  a107=(a074*a107);
  a107=(a065?a107:0);
  a092=(a092+a107);
  a092=(a091*a092);
  a077=(a024*a077);
  a092=(a092+a077);
  a092=(a007*a092);
  a048=(a048+a092);
  if (res[0]!=0) res[0][17]=a048;
  a048=arg[3]? arg[3][26] : 0;
  a092=(a048*a063);
  a077=arg[3]? arg[3][27] : 0;
  a107=(a077*a066);
  a092=(a092-a107);
  a049=(a049*a077);
  a028=(a028*a048);
  a049=(a049+a028);
  a049=casadi_sq(a049);
  a028=arg[0]? arg[0][4] : 0;
  a107=casadi_sq(a028);
  a034=arg[0]? arg[0][5] : 0;
  a052=casadi_sq(a034);
  a107=(a107+a052);
  a052=casadi_fmax(a049,a107);
  a041=pow(a052,a029);
  a090=(a041*a034);
  a097=arg[0]? arg[0][10] : 0;
  a079=(a090*a097);
  a092=(a092+a079);
  a079=(a041*a028);
  a085=arg[0]? arg[0][11] : 0;
  a050=(a079*a085);
  a092=(a092-a050);
  a050=casadi_fabs(a092);
  a055=(a050-a016);
  a055=(a055/a080);
  a071=casadi_fmax(a084,a055);
  a031=casadi_fmin(a068,a071);
  a070=sqrt(a052);
  a020=(a077+a070);
  a020=(a020-a048);
  a040=(a084<a020);
  a004=(a048*a077);
  a054=(a048-a077);
  a004=(a004/a054);
  a004=sqrt(a004);
  a100=(a100*a004);
  a004=arg[3]? arg[3][29] : 0;
  a004=casadi_sq(a004);
  a004=(a068-a004);
  a054=arg[3]? arg[3][28] : 0;
  a004=(a004/a054);
  a054=arg[3]? arg[3][31] : 0;
  a054=casadi_sq(a054);
  a054=(a068-a054);
  a056=arg[3]? arg[3][30] : 0;
  a054=(a054/a056);
  a004=(a004+a054);
  a100=(a100/a004);
  a004=arg[4]? arg[4][1] : 0;
  a004=casadi_fmax(a004,a083);
  a081=(a081/a004);
  a004=(a041*a028);
  a083=(a004*a097);
  a054=(a041*a034);
  a056=(a054*a085);
  a083=(a083+a056);
  a083=(a081*a083);
  a083=(a068+a083);
  a083=(a100*a083);
  a056=casadi_fmax(a059,a020);
  a051=pow(a056,a096);
  a095=(a083*a051);
  a095=(a040?a095:0);
  a062=casadi_fmax(a084,a095);
  a016=casadi_fmax(a016,a038);
  a038=casadi_fmax(a016,a050);
  a053=(a013/a038);
  a052=pow(a052,a003);
  a029=(a029*a052);
  a052=(a049<=a107);
  a107=(a107<=a049);
  a107=(a107+a052);
  a052=(a052/a107);
  a107=(2.*a028);
  a107=(a052*a107);
  a049=(a029*a107);
  a003=(a028*a049);
  a003=(a003+a041);
  a003=(a085*a003);
  a061=(a034*a049);
  a061=(a097*a061);
  a003=(a003-a061);
  a061=(a053*a003);
  a014=(a077*a066);
  a058=(a048*a063);
  a014=(a014-a058);
  a058=(a041*a028);
  a046=(a058*a085);
  a014=(a014+a046);
  a046=(a041*a034);
  a106=(a046*a097);
  a014=(a014-a106);
  a106=(a053/a038);
  a005=(a016<=a050);
  a050=(a050<=a016);
  a050=(a050+a005);
  a005=(a005/a050);
  a092=casadi_sign(a092);
  a050=(a034*a049);
  a050=(a097*a050);
  a016=(a028*a049);
  a016=(a016+a041);
  a016=(a085*a016);
  a050=(a050-a016);
  a050=(a092*a050);
  a016=(a005*a050);
  a108=(a106*a016);
  a108=(a014*a108);
  a061=(a061-a108);
  a061=(a062*a061);
  a108=(a053*a014);
  a109=(a084<=a095);
  a095=(a095<=a084);
  a095=(a095+a109);
  a109=(a109/a095);
  a095=(a028*a049);
  a095=(a095+a041);
  a095=(a097*a095);
  a110=(a034*a049);
  a110=(a085*a110);
  a095=(a095+a110);
  a095=(a081*a095);
  a095=(a100*a095);
  a095=(a051*a095);
  a110=(a096-a068);
  a056=pow(a056,a110);
  a096=(a096*a056);
  a056=(a059<=a020);
  a020=(a020<=a059);
  a020=(a020+a056);
  a056=(a056/a020);
  a070=(2.*a070);
  a107=(a107/a070);
  a107=(a056*a107);
  a107=(a096*a107);
  a107=(a083*a107);
  a095=(a095+a107);
  a095=(a109*a095);
  a107=(a108*a095);
  a107=(a040?a107:0);
  a061=(a061+a107);
  a061=(a031*a061);
  a107=(a108*a062);
  a020=(a071<=a068);
  a068=(a068<=a071);
  a068=(a068+a020);
  a020=(a020/a068);
  a068=(a084<=a055);
  a055=(a055<=a084);
  a055=(a055+a068);
  a068=(a068/a055);
  a050=(a050/a080);
  a050=(a068*a050);
  a050=(a020*a050);
  a055=(a107*a050);
  a061=(a061+a055);
  a055=(a048*a061);
  a061=(a077*a061);
  a055=(a055-a061);
  a055=(-a055);
  if (res[0]!=0) res[0][18]=a055;
  if (res[0]!=0) res[0][19]=a061;
  a061=(a013*a049);
  a061=(a061/a038);
  a055=(a013*a041);
  a055=(a055/a038);
  a084=(a055/a038);
  a071=(a084*a016);
  a061=(a061-a071);
  a061=(a014*a061);
  a071=(a055*a003);
  a061=(a061+a071);
  a061=(a062*a061);
  a071=(a055*a014);
  a059=(a071*a095);
  a059=(a040?a059:0);
  a061=(a061+a059);
  a061=(a031*a061);
  a059=(a071*a062);
  a110=(a059*a050);
  a061=(a061+a110);
  a061=(a034*a061);
  a110=(a062*a049);
  a111=(a041*a095);
  a111=(a040?a111:0);
  a110=(a110+a111);
  a110=(a028*a110);
  a111=(a041*a062);
  a110=(a110+a111);
  a061=(a061-a110);
  a061=(-a061);
  if (res[0]!=0) res[0][20]=a061;
  a061=(a062*a049);
  a110=(a041*a095);
  a110=(a040?a110:0);
  a061=(a061+a110);
  a061=(a034*a061);
  a049=(a013*a049);
  a049=(a049/a038);
  a110=(a013*a041);
  a110=(a110/a038);
  a111=(a110/a038);
  a016=(a111*a016);
  a049=(a049-a016);
  a049=(a014*a049);
  a003=(a110*a003);
  a049=(a049+a003);
  a049=(a062*a049);
  a003=(a110*a014);
  a095=(a003*a095);
  a095=(a040?a095:0);
  a049=(a049+a095);
  a049=(a031*a049);
  a095=(a003*a062);
  a050=(a095*a050);
  a049=(a049+a050);
  a049=(a028*a049);
  a050=(a095*a031);
  a049=(a049+a050);
  a061=(a061+a049);
  if (res[0]!=0) res[0][21]=a061;
  a061=(2.*a034);
  a052=(a052*a061);
  a029=(a029*a052);
  a061=(a028*a029);
  a061=(a085*a061);
  a049=(a034*a029);
  a049=(a049+a041);
  a049=(a097*a049);
  a061=(a061-a049);
  a049=(a053*a061);
  a050=(a034*a029);
  a050=(a050+a041);
  a050=(a097*a050);
  a016=(a028*a029);
  a016=(a085*a016);
  a050=(a050-a016);
  a050=(a092*a050);
  a016=(a005*a050);
  a112=(a106*a016);
  a112=(a014*a112);
  a049=(a049-a112);
  a049=(a062*a049);
  a112=(a028*a029);
  a097=(a097*a112);
  a112=(a034*a029);
  a112=(a112+a041);
  a085=(a085*a112);
  a097=(a097+a085);
  a097=(a081*a097);
  a097=(a100*a097);
  a097=(a051*a097);
  a052=(a052/a070);
  a056=(a056*a052);
  a096=(a096*a056);
  a083=(a083*a096);
  a097=(a097+a083);
  a097=(a109*a097);
  a083=(a108*a097);
  a083=(a040?a083:0);
  a049=(a049+a083);
  a049=(a031*a049);
  a050=(a050/a080);
  a050=(a068*a050);
  a050=(a020*a050);
  a083=(a107*a050);
  a049=(a049+a083);
  a083=(a048*a049);
  a049=(a077*a049);
  a083=(a083-a049);
  a083=(-a083);
  if (res[0]!=0) res[0][22]=a083;
  if (res[0]!=0) res[0][23]=a049;
  a049=(a013*a029);
  a049=(a049/a038);
  a083=(a084*a016);
  a049=(a049-a083);
  a049=(a014*a049);
  a083=(a055*a061);
  a049=(a049+a083);
  a049=(a062*a049);
  a083=(a071*a097);
  a083=(a040?a083:0);
  a049=(a049+a083);
  a049=(a031*a049);
  a083=(a059*a050);
  a049=(a049+a083);
  a049=(a034*a049);
  a083=(a059*a031);
  a049=(a049+a083);
  a083=(a062*a029);
  a096=(a041*a097);
  a096=(a040?a096:0);
  a083=(a083+a096);
  a083=(a028*a083);
  a049=(a049-a083);
  a049=(-a049);
  if (res[0]!=0) res[0][24]=a049;
  a049=(a062*a029);
  a083=(a041*a097);
  a083=(a040?a083:0);
  a049=(a049+a083);
  a049=(a034*a049);
  a083=(a041*a062);
  a049=(a049+a083);
  a013=(a013*a029);
  a013=(a013/a038);
  a016=(a111*a016);
  a013=(a013-a016);
  a013=(a014*a013);
  a061=(a110*a061);
  a013=(a013+a061);
  a013=(a062*a013);
  a097=(a003*a097);
  a097=(a040?a097:0);
  a013=(a013+a097);
  a013=(a031*a013);
  a050=(a095*a050);
  a013=(a013+a050);
  a013=(a028*a013);
  a049=(a049+a013);
  if (res[0]!=0) res[0][25]=a049;
  a049=(a077-a048);
  a013=(a053*a049);
  a050=(a048-a077);
  a050=(a092*a050);
  a097=(a005*a050);
  a061=(a106*a097);
  a061=(a014*a061);
  a013=(a013-a061);
  a013=(a062*a013);
  a013=(a031*a013);
  a050=(a050/a080);
  a050=(a068*a050);
  a050=(a020*a050);
  a061=(a107*a050);
  a013=(a013+a061);
  a061=(a048*a013);
  a016=(a067*a000);
  a038=(a009*a000);
  a029=(a082*a038);
  a083=(a086*a029);
  a083=(a087*a083);
  a016=(a016-a083);
  a016=(a015*a016);
  a016=(a091*a016);
  a038=(a038/a080);
  a038=(a023*a038);
  a038=(a089*a038);
  a083=(a018*a038);
  a016=(a016+a083);
  a016=(a000*a016);
  a013=(a077*a013);
  a016=(a016+a013);
  a061=(a061-a016);
  a063=(2.*a063);
  a016=(a002*a063);
  a016=(a006*a016);
  a066=(2.*a066);
  a083=(a008*a066);
  a083=(a011*a083);
  a083=(a016+a083);
  a096=(a022*a083);
  a061=(a061+a096);
  a002=(a002*a063);
  a002=(a019*a002);
  a096=(a008*a066);
  a096=(a021*a096);
  a096=(a002+a096);
  a056=(a012*a096);
  a061=(a061-a056);
  a056=(a027*a066);
  a056=(a011*a056);
  a052=(a016+a056);
  a070=(a030*a066);
  a070=(a010*a070);
  a052=(a052+a070);
  a070=(a017*a052);
  a061=(a061+a070);
  a070=(a027*a066);
  a070=(a021*a070);
  a085=(a002+a070);
  a112=(a030*a066);
  a112=(a039*a112);
  a085=(a085+a112);
  a112=(a093*a085);
  a061=(a061-a112);
  a016=(a016+a056);
  a056=(a045*a066);
  a056=(a010*a056);
  a016=(a016+a056);
  a056=(a033*a016);
  a061=(a061+a056);
  a002=(a002+a070);
  a070=(a045*a066);
  a070=(a039*a070);
  a002=(a002+a070);
  a070=(a043*a002);
  a061=(a061-a070);
  a061=(-a061);
  if (res[0]!=0) res[0][26]=a061;
  a061=(a098*a052);
  a061=(a061-a013);
  a013=(a101*a085);
  a061=(a061-a013);
  a013=(a035*a016);
  a061=(a061+a013);
  a013=(a104*a002);
  a061=(a061-a013);
  a013=(a032*a096);
  a013=(a011*a013);
  a061=(a061-a013);
  a013=(a105*a083);
  a013=(a021*a013);
  a061=(a061+a013);
  a061=(-a061);
  if (res[0]!=0) res[0][27]=a061;
  a061=(a042*a000);
  a013=(a025*a029);
  a013=(a087*a013);
  a061=(a061-a013);
  a061=(a015*a061);
  a061=(a091*a061);
  a013=(a069*a038);
  a061=(a061+a013);
  a061=(a088*a061);
  a096=(a001*a096);
  a061=(a061+a096);
  a085=(a026*a085);
  a061=(a061+a085);
  a002=(a036*a002);
  a061=(a061+a002);
  a099=(a099*a063);
  a019=(a019*a099);
  a061=(a061+a019);
  a061=(-a061);
  if (res[0]!=0) res[0][28]=a061;
  a083=(a001*a083);
  a061=(a076*a000);
  a029=(a075*a029);
  a029=(a087*a029);
  a061=(a061-a029);
  a061=(a015*a061);
  a061=(a091*a061);
  a038=(a024*a038);
  a061=(a061+a038);
  a061=(a007*a061);
  a061=(a083-a061);
  a052=(a026*a052);
  a061=(a061+a052);
  a016=(a036*a016);
  a061=(a061+a016);
  a057=(a057*a063);
  a006=(a006*a057);
  a061=(a061+a006);
  a061=(-a061);
  if (res[0]!=0) res[0][29]=a061;
  a061=(a055*a049);
  a006=(a084*a097);
  a006=(a014*a006);
  a061=(a061-a006);
  a061=(a062*a061);
  a061=(a031*a061);
  a006=(a059*a050);
  a061=(a061+a006);
  a061=(a034*a061);
  a061=(a061+a096);
  a061=(a061+a085);
  a061=(a061+a002);
  a061=(-a061);
  if (res[0]!=0) res[0][30]=a061;
  a049=(a110*a049);
  a097=(a111*a097);
  a097=(a014*a097);
  a049=(a049-a097);
  a049=(a062*a049);
  a049=(a031*a049);
  a050=(a095*a050);
  a049=(a049+a050);
  a049=(a028*a049);
  a083=(a083-a049);
  a083=(a083+a052);
  a083=(a083+a016);
  a083=(-a083);
  if (res[0]!=0) res[0][31]=a083;
  a083=(a092*a077);
  a016=(a005*a083);
  a052=(a106*a016);
  a052=(a014*a052);
  a049=(a053*a077);
  a052=(a052+a049);
  a052=(a062*a052);
  a052=(a031*a052);
  a083=(a083/a080);
  a083=(a068*a083);
  a083=(a020*a083);
  a049=(a107*a083);
  a052=(a052-a049);
  a049=(a048*a052);
  a052=(a077*a052);
  a049=(a049-a052);
  a050=(a008*a066);
  a050=(a011*a050);
  a022=(a022*a050);
  a049=(a049+a022);
  a008=(a008*a066);
  a008=(a021*a008);
  a012=(a012*a008);
  a049=(a049-a012);
  a012=(a027*a066);
  a012=(a011*a012);
  a022=(a030*a066);
  a022=(a010*a022);
  a022=(a012+a022);
  a017=(a017*a022);
  a049=(a049+a017);
  a027=(a027*a066);
  a027=(a021*a027);
  a030=(a030*a066);
  a030=(a039*a030);
  a030=(a027+a030);
  a093=(a093*a030);
  a049=(a049-a093);
  a093=(a045*a066);
  a010=(a010*a093);
  a012=(a012+a010);
  a033=(a033*a012);
  a049=(a049+a033);
  a045=(a045*a066);
  a039=(a039*a045);
  a027=(a027+a039);
  a043=(a043*a027);
  a049=(a049-a043);
  a049=(-a049);
  if (res[0]!=0) res[0][32]=a049;
  a098=(a098*a022);
  a098=(a098-a052);
  a101=(a101*a030);
  a098=(a098-a101);
  a035=(a035*a012);
  a098=(a098+a035);
  a104=(a104*a027);
  a098=(a098-a104);
  a032=(a032*a008);
  a011=(a011*a032);
  a098=(a098-a011);
  a105=(a105*a050);
  a021=(a021*a105);
  a098=(a098+a021);
  a098=(-a098);
  if (res[0]!=0) res[0][33]=a098;
  a008=(a001*a008);
  a030=(a026*a030);
  a098=(a008+a030);
  a027=(a036*a027);
  a098=(a098+a027);
  a098=(-a098);
  if (res[0]!=0) res[0][34]=a098;
  a001=(a001*a050);
  a026=(a026*a022);
  a022=(a001+a026);
  a036=(a036*a012);
  a022=(a022+a036);
  a022=(-a022);
  if (res[0]!=0) res[0][35]=a022;
  a022=(a084*a016);
  a022=(a014*a022);
  a012=(a055*a077);
  a022=(a022+a012);
  a022=(a062*a022);
  a022=(a031*a022);
  a012=(a059*a083);
  a022=(a022-a012);
  a022=(a034*a022);
  a022=(a022+a008);
  a022=(a022+a030);
  a022=(a022+a027);
  a022=(-a022);
  if (res[0]!=0) res[0][36]=a022;
  a016=(a111*a016);
  a016=(a014*a016);
  a022=(a110*a077);
  a016=(a016+a022);
  a016=(a062*a016);
  a016=(a031*a016);
  a083=(a095*a083);
  a016=(a016-a083);
  a016=(a028*a016);
  a001=(a001-a016);
  a001=(a001+a026);
  a001=(a001+a036);
  a001=(-a001);
  if (res[0]!=0) res[0][37]=a001;
  a001=(a009*a072);
  a036=(a082*a001);
  a026=(a086*a036);
  a026=(a087*a026);
  a016=(a067*a072);
  a026=(a026-a016);
  a026=(a015*a026);
  a102=(a103*a102);
  a102=(a044*a102);
  a102=(a094*a102);
  a102=(a073*a102);
  a016=(a060*a102);
  a016=(a065?a016:0);
  a026=(a026+a016);
  a026=(a091*a026);
  a001=(a001/a080);
  a001=(a023*a001);
  a001=(a089*a001);
  a016=(a018*a001);
  a026=(a026-a016);
  a026=(a000*a026);
  if (res[0]!=0) res[0][38]=a026;
  a026=(a025*a036);
  a026=(a087*a026);
  a016=(a042*a072);
  a026=(a026-a016);
  a026=(a015*a026);
  a016=(a078*a102);
  a016=(a065?a016:0);
  a026=(a026+a016);
  a026=(a091*a026);
  a016=(a069*a001);
  a026=(a026-a016);
  a026=(a088*a026);
  a016=(a047*a102);
  a016=(a007*a016);
  a016=(-a016);
  a016=(a065?a016:0);
  a026=(a026+a016);
  a026=(-a026);
  if (res[0]!=0) res[0][39]=a026;
  a026=(a047*a102);
  a026=(a088*a026);
  a026=(a065?a026:0);
  a036=(a075*a036);
  a036=(a087*a036);
  a072=(a076*a072);
  a036=(a036-a072);
  a036=(a015*a036);
  a102=(a074*a102);
  a102=(a065?a102:0);
  a036=(a036+a102);
  a036=(a091*a036);
  a001=(a024*a001);
  a036=(a036-a001);
  a036=(a007*a036);
  a026=(a026+a036);
  if (res[0]!=0) res[0][40]=a026;
  a067=(a067*a037);
  a009=(a009*a037);
  a082=(a082*a009);
  a086=(a086*a082);
  a086=(a087*a086);
  a067=(a067-a086);
  a067=(a015*a067);
  a103=(a103*a064);
  a044=(a044*a103);
  a094=(a094*a044);
  a073=(a073*a094);
  a060=(a060*a073);
  a060=(a065?a060:0);
  a067=(a067+a060);
  a067=(a091*a067);
  a009=(a009/a080);
  a023=(a023*a009);
  a089=(a089*a023);
  a018=(a018*a089);
  a067=(a067+a018);
  a000=(a000*a067);
  if (res[0]!=0) res[0][41]=a000;
  a042=(a042*a037);
  a025=(a025*a082);
  a025=(a087*a025);
  a042=(a042-a025);
  a042=(a015*a042);
  a078=(a078*a073);
  a078=(a065?a078:0);
  a042=(a042+a078);
  a042=(a091*a042);
  a069=(a069*a089);
  a042=(a042+a069);
  a042=(a088*a042);
  a069=(a047*a073);
  a069=(a007*a069);
  a069=(-a069);
  a069=(a065?a069:0);
  a042=(a042+a069);
  a042=(-a042);
  if (res[0]!=0) res[0][42]=a042;
  a047=(a047*a073);
  a088=(a088*a047);
  a088=(a065?a088:0);
  a076=(a076*a037);
  a075=(a075*a082);
  a087=(a087*a075);
  a076=(a076-a087);
  a015=(a015*a076);
  a074=(a074*a073);
  a065=(a065?a074:0);
  a015=(a015+a065);
  a091=(a091*a015);
  a024=(a024*a089);
  a091=(a091+a024);
  a007=(a007*a091);
  a088=(a088+a007);
  if (res[0]!=0) res[0][43]=a088;
  a004=(a081*a004);
  a004=(a100*a004);
  a004=(a051*a004);
  a004=(a109*a004);
  a088=(a108*a004);
  a088=(a040?a088:0);
  a090=(a092*a090);
  a007=(a005*a090);
  a091=(a106*a007);
  a091=(a014*a091);
  a024=(a053*a046);
  a091=(a091+a024);
  a091=(a062*a091);
  a088=(a088-a091);
  a088=(a031*a088);
  a090=(a090/a080);
  a090=(a068*a090);
  a090=(a020*a090);
  a091=(a107*a090);
  a088=(a088+a091);
  a091=(a048*a088);
  a088=(a077*a088);
  a091=(a091-a088);
  a091=(-a091);
  if (res[0]!=0) res[0][44]=a091;
  if (res[0]!=0) res[0][45]=a088;
  a088=(a071*a004);
  a088=(a040?a088:0);
  a091=(a084*a007);
  a091=(a014*a091);
  a024=(a055*a046);
  a091=(a091+a024);
  a091=(a062*a091);
  a088=(a088-a091);
  a088=(a031*a088);
  a091=(a059*a090);
  a088=(a088+a091);
  a088=(a034*a088);
  a091=(a041*a004);
  a091=(a028*a091);
  a091=(-a091);
  a091=(a040?a091:0);
  a088=(a088+a091);
  a088=(-a088);
  if (res[0]!=0) res[0][46]=a088;
  a088=(a041*a004);
  a088=(a034*a088);
  a088=(a040?a088:0);
  a004=(a003*a004);
  a004=(a040?a004:0);
  a007=(a111*a007);
  a007=(a014*a007);
  a046=(a110*a046);
  a007=(a007+a046);
  a007=(a062*a007);
  a004=(a004-a007);
  a004=(a031*a004);
  a090=(a095*a090);
  a004=(a004+a090);
  a004=(a028*a004);
  a088=(a088+a004);
  if (res[0]!=0) res[0][47]=a088;
  a092=(a092*a079);
  a005=(a005*a092);
  a106=(a106*a005);
  a106=(a014*a106);
  a053=(a053*a058);
  a106=(a106+a053);
  a106=(a062*a106);
  a081=(a081*a054);
  a100=(a100*a081);
  a051=(a051*a100);
  a109=(a109*a051);
  a108=(a108*a109);
  a108=(a040?a108:0);
  a106=(a106+a108);
  a106=(a031*a106);
  a092=(a092/a080);
  a068=(a068*a092);
  a020=(a020*a068);
  a107=(a107*a020);
  a106=(a106-a107);
  a048=(a048*a106);
  a077=(a077*a106);
  a048=(a048-a077);
  a048=(-a048);
  if (res[0]!=0) res[0][48]=a048;
  if (res[0]!=0) res[0][49]=a077;
  a084=(a084*a005);
  a084=(a014*a084);
  a055=(a055*a058);
  a084=(a084+a055);
  a084=(a062*a084);
  a071=(a071*a109);
  a071=(a040?a071:0);
  a084=(a084+a071);
  a084=(a031*a084);
  a059=(a059*a020);
  a084=(a084-a059);
  a084=(a034*a084);
  a059=(a041*a109);
  a059=(a028*a059);
  a059=(-a059);
  a059=(a040?a059:0);
  a084=(a084+a059);
  a084=(-a084);
  if (res[0]!=0) res[0][50]=a084;
  a041=(a041*a109);
  a034=(a034*a041);
  a034=(a040?a034:0);
  a111=(a111*a005);
  a014=(a014*a111);
  a110=(a110*a058);
  a014=(a014+a110);
  a062=(a062*a014);
  a003=(a003*a109);
  a040=(a040?a003:0);
  a062=(a062+a040);
  a031=(a031*a062);
  a095=(a095*a020);
  a031=(a031-a095);
  a028=(a028*a031);
  a034=(a034+a028);
  if (res[0]!=0) res[0][51]=a034;
  return 0;
}

/* residual_jacobian_inputs:(i0[12],i1[6],i2[2],i3[39],i4[2])->(o0[6x2,2nz],o1[6x39,157nz],o2[6x2,7nz]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  casadi_real a168, a169, a170, a171, a172;
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
  a011=(a002+a003);
  a012=arg[0]? arg[0][1] : 0;
  a011=(a011+a012);
  a013=sin(a011);
  a014=(a010*a013);
  a015=(a009+a014);
  a016=arg[3]? arg[3][12] : 0;
  a017=arg[3]? arg[3][32] : 0;
  a002=(a002+a017);
  a002=(a002+a003);
  a002=(a002+a012);
  a012=sin(a002);
  a003=(a016*a012);
  a015=(a015+a003);
  a017=(a006*a015);
  a018=arg[3]? arg[3][13] : 0;
  a019=(a009+a014);
  a020=arg[3]? arg[3][15] : 0;
  a021=(a020*a012);
  a019=(a019+a021);
  a022=(a018*a019);
  a023=(a017+a022);
  a024=arg[3]? arg[3][9] : 0;
  a025=arg[3]? arg[3][11] : 0;
  a026=(a025*a013);
  a009=(a009+a026);
  a026=(a024*a009);
  a023=(a023+a026);
  a027=(a005*a023);
  a027=(a001*a027);
  a028=(a007*a005);
  a029=cos(a011);
  a030=(a010*a029);
  a031=(a028+a030);
  a032=cos(a002);
  a033=(a016*a032);
  a031=(a031+a033);
  a034=(a006*a031);
  a035=(a028+a030);
  a036=(a020*a032);
  a035=(a035+a036);
  a037=(a018*a035);
  a038=(a034+a037);
  a039=(a025*a029);
  a028=(a028+a039);
  a039=(a024*a028);
  a038=(a038+a039);
  a040=(a008*a038);
  a040=(a001*a040);
  a027=(a027-a040);
  a040=(a007*a001);
  a041=(a040*a005);
  a042=arg[0]? arg[0][7] : 0;
  a042=(a000+a042);
  a043=casadi_sq(a042);
  a044=(a010*a043);
  a045=(a044*a029);
  a046=(a041+a045);
  a047=(a016*a043);
  a048=(a047*a032);
  a046=(a046+a048);
  a048=(a006*a046);
  a049=arg[3]? arg[3][17] : 0;
  a050=(a049*a006);
  a048=(a048+a050);
  a050=arg[1]? arg[1][4] : 0;
  a051=arg[1]? arg[1][2] : 0;
  a052=(a050+a051);
  a053=(a006*a052);
  a048=(a048-a053);
  a003=(a014+a003);
  a053=arg[1]? arg[1][1] : 0;
  a054=(a006*a053);
  a055=(a003*a054);
  a048=(a048+a055);
  a055=(2.*a015);
  a056=arg[1]? arg[1][0] : 0;
  a057=(a006*a056);
  a055=(a055*a057);
  a048=(a048+a055);
  a045=(a041+a045);
  a055=(a020*a043);
  a058=(a055*a032);
  a045=(a045+a058);
  a058=(a018*a045);
  a059=(a049*a018);
  a058=(a058+a059);
  a059=(a050+a051);
  a060=(a018*a059);
  a058=(a058-a060);
  a014=(a014+a021);
  a021=(a018*a053);
  a060=(a014*a021);
  a058=(a058+a060);
  a060=(2.*a019);
  a061=(a018*a056);
  a060=(a060*a061);
  a058=(a058+a060);
  a060=(a048+a058);
  a062=(a025*a043);
  a063=(a062*a029);
  a041=(a041+a063);
  a063=(a024*a041);
  a064=(a049*a024);
  a063=(a063+a064);
  a064=(a050+a051);
  a065=(a024*a064);
  a063=(a063-a065);
  a065=(a024*a053);
  a066=(a013*a065);
  a067=(a025*a066);
  a063=(a063+a067);
  a067=(2.*a009);
  a068=(a024*a056);
  a067=(a067*a068);
  a063=(a063+a067);
  a060=(a060+a063);
  a067=(a008*a060);
  a027=(a027+a067);
  a067=arg[1]? arg[1][5] : 0;
  a069=arg[1]? arg[1][3] : 0;
  a070=(a067+a069);
  a071=(a006*a070);
  a072=(a007*a001);
  a073=(a072*a008);
  a074=(a010*a043);
  a075=(a074*a013);
  a076=(a073+a075);
  a077=(a016*a043);
  a078=(a077*a012);
  a076=(a076+a078);
  a078=(a006*a076);
  a079=arg[3]? arg[3][18] : 0;
  a080=(a079*a006);
  a078=(a078+a080);
  a071=(a071-a078);
  a033=(a030+a033);
  a078=(a033*a054);
  a071=(a071+a078);
  a078=(2.*a031);
  a078=(a078*a057);
  a071=(a071+a078);
  a078=(a067+a069);
  a057=(a018*a078);
  a075=(a073+a075);
  a080=(a020*a043);
  a081=(a080*a012);
  a075=(a075+a081);
  a081=(a018*a075);
  a082=(a079*a018);
  a081=(a081+a082);
  a057=(a057-a081);
  a030=(a030+a036);
  a036=(a030*a021);
  a057=(a057+a036);
  a036=(2.*a035);
  a036=(a036*a061);
  a057=(a057+a036);
  a036=(a071+a057);
  a061=(a067+a069);
  a081=(a024*a061);
  a082=(a025*a043);
  a083=(a082*a013);
  a073=(a073+a083);
  a083=(a024*a073);
  a084=(a079*a024);
  a083=(a083+a084);
  a081=(a081-a083);
  a083=(a029*a065);
  a084=(a025*a083);
  a081=(a081+a084);
  a084=(2.*a028);
  a084=(a084*a068);
  a081=(a081+a084);
  a036=(a036+a081);
  a084=(a005*a036);
  a027=(a027+a084);
  if (res[1]!=0) res[1][0]=a027;
  a027=(a006*a003);
  a084=(a018*a014);
  a068=(a027+a084);
  a085=(a025*a024);
  a086=(a085*a013);
  a068=(a068+a086);
  a087=(a005*a068);
  a087=(a001*a087);
  a088=(a006*a033);
  a089=(a018*a030);
  a090=(a088+a089);
  a091=(a025*a024);
  a092=(a091*a029);
  a090=(a090+a092);
  a093=(a008*a090);
  a093=(a001*a093);
  a087=(a087-a093);
  a093=(a006*a056);
  a094=(a003*a093);
  a095=(a018*a056);
  a096=(a014*a095);
  a097=(a094+a096);
  a098=(a024*a056);
  a099=(a013*a098);
  a100=(a025*a099);
  a097=(a097+a100);
  a101=(a008*a097);
  a087=(a087+a101);
  a101=(a033*a093);
  a102=(a030*a095);
  a103=(a101+a102);
  a104=(a029*a098);
  a105=(a025*a104);
  a103=(a103+a105);
  a106=(a005*a103);
  a087=(a087+a106);
  if (res[1]!=0) res[1][1]=a087;
  a087=(a006+a018);
  a087=(a087+a024);
  a106=(a005*a087);
  a106=(a001*a106);
  a107=(a006*a056);
  a108=(a018*a056);
  a109=(a107+a108);
  a110=(a024*a056);
  a109=(a109+a110);
  a111=(a008*a109);
  a106=(a106+a111);
  a106=(-a106);
  if (res[1]!=0) res[1][2]=a106;
  a106=(a006*a056);
  a111=(a018*a056);
  a112=(a106+a111);
  a113=(a024*a056);
  a112=(a112+a113);
  a114=(a005*a112);
  a115=(a006+a018);
  a115=(a115+a024);
  a116=(a008*a115);
  a116=(a001*a116);
  a114=(a114-a116);
  if (res[1]!=0) res[1][3]=a114;
  a114=(a006+a018);
  a114=(a114+a024);
  a116=(a005*a114);
  a116=(a001*a116);
  a117=(a006*a056);
  a118=(a018*a056);
  a119=(a117+a118);
  a120=(a024*a056);
  a119=(a119+a120);
  a121=(a008*a119);
  a116=(a116+a121);
  a116=(-a116);
  if (res[1]!=0) res[1][4]=a116;
  a116=(a006*a056);
  a121=(a018*a056);
  a122=(a116+a121);
  a123=(a024*a056);
  a122=(a122+a123);
  a124=(a005*a122);
  a125=(a006+a018);
  a125=(a125+a024);
  a126=(a008*a125);
  a126=(a001*a126);
  a124=(a124-a126);
  if (res[1]!=0) res[1][5]=a124;
  a124=arg[3]? arg[3][7] : 0;
  a126=(a124*a049);
  a127=(a126*a008);
  a128=(a124*a079);
  a129=(a128*a005);
  a127=(a127-a129);
  a129=(a005*a069);
  a130=(a124*a129);
  a127=(a127+a130);
  a130=(a008*a051);
  a131=(a124*a130);
  a127=(a127-a131);
  a131=casadi_sq(a124);
  a131=(a131*a056);
  a127=(a127+a131);
  if (res[1]!=0) res[1][6]=a127;
  a127=(a001*a005);
  a131=(a124*a127);
  a131=(a131+a049);
  a131=(a051-a131);
  a132=(a008*a056);
  a133=(a124*a132);
  a131=(a131-a133);
  if (res[1]!=0) res[1][7]=a131;
  a131=(a001*a008);
  a133=(a124*a131);
  a133=(a133+a079);
  a133=(a069-a133);
  a134=(a005*a056);
  a135=(a124*a134);
  a133=(a133+a135);
  if (res[1]!=0) res[1][8]=a133;
  if (res[1]!=0) res[1][9]=a056;
  a133=arg[3]? arg[3][5] : 0;
  a008=(a133*a008);
  a135=(a049*a008);
  a005=(a133*a005);
  a136=(a079*a005);
  a135=(a135-a136);
  a129=(a133*a129);
  a135=(a135+a129);
  a130=(a133*a130);
  a135=(a135-a130);
  a130=(2.*a124);
  a129=(a133*a056);
  a130=(a130*a129);
  a135=(a135+a130);
  if (res[1]!=0) res[1][10]=a135;
  a127=(a133*a127);
  a132=(a133*a132);
  a127=(a127+a132);
  a127=(-a127);
  if (res[1]!=0) res[1][11]=a127;
  a134=(a133*a134);
  a131=(a133*a131);
  a134=(a134-a131);
  if (res[1]!=0) res[1][12]=a134;
  a134=(a017+a022);
  a131=(a029*a134);
  a131=(a043*a131);
  a127=(a034+a037);
  a132=(a013*a127);
  a132=(a043*a132);
  a131=(a131-a132);
  a132=(a015*a054);
  a135=(a019*a021);
  a130=(a132+a135);
  a130=(a130+a048);
  a130=(a130+a058);
  a129=(a013*a130);
  a131=(a131+a129);
  a054=(a031*a054);
  a021=(a035*a021);
  a129=(a054+a021);
  a129=(a129+a071);
  a129=(a129+a057);
  a136=(a029*a129);
  a131=(a131+a136);
  if (res[1]!=0) res[1][13]=a131;
  a131=(a027+a084);
  a136=(a029*a131);
  a136=(a043*a136);
  a137=(a088+a089);
  a138=(a013*a137);
  a138=(a043*a138);
  a136=(a136-a138);
  a138=(a006*a046);
  a139=(a049*a006);
  a138=(a138+a139);
  a139=(a050+a051);
  a140=(a006*a139);
  a138=(a138-a140);
  a140=(2.*a003);
  a141=(a006*a053);
  a140=(a140*a141);
  a138=(a138+a140);
  a140=(a015*a093);
  a138=(a138+a140);
  a140=(a018*a045);
  a142=(a049*a018);
  a140=(a140+a142);
  a142=(a018*a139);
  a140=(a140-a142);
  a142=(2.*a014);
  a143=(a018*a053);
  a142=(a142*a143);
  a140=(a140+a142);
  a142=(a019*a095);
  a140=(a140+a142);
  a142=(a138+a140);
  a142=(a142+a094);
  a142=(a142+a096);
  a144=(a013*a142);
  a136=(a136+a144);
  a144=(a067+a069);
  a145=(a006*a144);
  a146=(a006*a076);
  a147=(a079*a006);
  a146=(a146+a147);
  a145=(a145-a146);
  a146=(2.*a033);
  a146=(a146*a141);
  a145=(a145+a146);
  a093=(a031*a093);
  a145=(a145+a093);
  a093=(a018*a144);
  a146=(a018*a075);
  a141=(a079*a018);
  a146=(a146+a141);
  a093=(a093-a146);
  a146=(2.*a030);
  a146=(a146*a143);
  a093=(a093+a146);
  a095=(a035*a095);
  a093=(a093+a095);
  a095=(a145+a093);
  a095=(a095+a101);
  a095=(a095+a102);
  a146=(a029*a095);
  a136=(a136+a146);
  if (res[1]!=0) res[1][14]=a136;
  a136=(a006+a018);
  a146=(a029*a136);
  a146=(a043*a146);
  a143=(a006*a053);
  a141=(a018*a053);
  a147=(a143+a141);
  a147=(a147+a107);
  a147=(a147+a108);
  a148=(a013*a147);
  a146=(a146+a148);
  a146=(-a146);
  if (res[1]!=0) res[1][15]=a146;
  a146=(a006*a053);
  a148=(a018*a053);
  a149=(a146+a148);
  a149=(a149+a106);
  a149=(a149+a111);
  a150=(a029*a149);
  a151=(a006+a018);
  a152=(a013*a151);
  a152=(a043*a152);
  a150=(a150-a152);
  if (res[1]!=0) res[1][16]=a150;
  a150=(a006+a018);
  a152=(a029*a150);
  a152=(a043*a152);
  a153=(a006*a053);
  a154=(a018*a053);
  a155=(a153+a154);
  a155=(a155+a117);
  a155=(a155+a118);
  a156=(a013*a155);
  a152=(a152+a156);
  a152=(-a152);
  if (res[1]!=0) res[1][17]=a152;
  a152=(a006*a053);
  a156=(a018*a053);
  a157=(a152+a156);
  a157=(a157+a116);
  a157=(a157+a121);
  a158=(a029*a157);
  a159=(a006+a018);
  a160=(a013*a159);
  a160=(a043*a160);
  a158=(a158-a160);
  if (res[1]!=0) res[1][18]=a158;
  a158=(a009*a041);
  a160=(a028*a073);
  a158=(a158-a160);
  a160=(a079*a028);
  a158=(a158-a160);
  a160=(a049*a009);
  a158=(a158+a160);
  a061=(a028*a061);
  a158=(a158+a061);
  a064=(a009*a064);
  a158=(a158-a064);
  a064=(a025*a028);
  a061=(a064*a029);
  a160=(a025*a009);
  a161=(a160*a013);
  a061=(a061+a161);
  a161=(a061*a053);
  a158=(a158+a161);
  a161=casadi_sq(a028);
  a162=casadi_sq(a009);
  a161=(a161+a162);
  a161=(a161*a056);
  a158=(a158+a161);
  if (res[1]!=0) res[1][19]=a158;
  a158=(a025*a049);
  a161=(a158*a013);
  a162=(a073*a029);
  a163=(a025*a162);
  a161=(a161-a163);
  a163=(a041*a013);
  a164=(a025*a163);
  a161=(a161+a164);
  a164=(a025*a079);
  a165=(a164*a029);
  a161=(a161-a165);
  a165=(a029*a144);
  a166=(a025*a165);
  a161=(a161+a166);
  a166=(a013*a139);
  a167=(a025*a166);
  a161=(a161-a167);
  a167=casadi_sq(a025);
  a167=(a167*a053);
  a161=(a161+a167);
  a061=(a061*a056);
  a161=(a161+a061);
  if (res[1]!=0) res[1][20]=a161;
  a161=(a041+a049);
  a161=(a050-a161);
  a161=(a161+a051);
  a061=(a013*a053);
  a167=(a025*a061);
  a161=(a161-a167);
  a167=(a009*a056);
  a161=(a161-a167);
  if (res[1]!=0) res[1][21]=a161;
  a161=(a073+a079);
  a161=(a067-a161);
  a161=(a161+a069);
  a167=(a029*a053);
  a168=(a025*a167);
  a161=(a161+a168);
  a168=(a028*a056);
  a161=(a161+a168);
  if (res[1]!=0) res[1][22]=a161;
  a161=(a050+a051);
  a168=(a041+a049);
  a168=(a161-a168);
  a169=(a013*a053);
  a170=(a025*a169);
  a168=(a168-a170);
  a170=(a009*a056);
  a168=(a168-a170);
  if (res[1]!=0) res[1][23]=a168;
  a168=(a067+a069);
  a170=(a073+a079);
  a170=(a168-a170);
  a171=(a029*a053);
  a172=(a025*a171);
  a170=(a170+a172);
  a172=(a028*a056);
  a170=(a170+a172);
  if (res[1]!=0) res[1][24]=a170;
  a170=(a053+a056);
  if (res[1]!=0) res[1][25]=a170;
  a170=(a053+a056);
  if (res[1]!=0) res[1][26]=a170;
  a170=(a029*a026);
  a170=(a043*a170);
  a172=(a013*a039);
  a172=(a043*a172);
  a170=(a170-a172);
  a066=(a009*a066);
  a170=(a170+a066);
  a083=(a028*a083);
  a170=(a170+a083);
  a083=(a013*a063);
  a170=(a170+a083);
  a083=(a029*a081);
  a170=(a170+a083);
  if (res[1]!=0) res[1][27]=a170;
  a170=(a024*a013);
  a083=(a049*a170);
  a162=(a024*a162);
  a083=(a083-a162);
  a163=(a024*a163);
  a083=(a083+a163);
  a163=(a024*a029);
  a162=(a079*a163);
  a083=(a083-a162);
  a165=(a024*a165);
  a083=(a083+a165);
  a166=(a024*a166);
  a083=(a083-a166);
  a166=(2.*a025);
  a165=(a024*a053);
  a166=(a166*a165);
  a083=(a083+a166);
  a166=(a029*a086);
  a166=(a043*a166);
  a083=(a083+a166);
  a166=(a013*a092);
  a166=(a043*a166);
  a083=(a083-a166);
  a099=(a009*a099);
  a083=(a083+a099);
  a104=(a028*a104);
  a083=(a083+a104);
  a104=(a013*a100);
  a083=(a083+a104);
  a104=(a029*a105);
  a083=(a083+a104);
  if (res[1]!=0) res[1][28]=a083;
  a061=(a024*a061);
  a083=(a029*a024);
  a083=(a043*a083);
  a061=(a061+a083);
  a083=(a013*a110);
  a061=(a061+a083);
  a061=(-a061);
  if (res[1]!=0) res[1][29]=a061;
  a167=(a024*a167);
  a061=(a013*a024);
  a061=(a043*a061);
  a167=(a167-a061);
  a061=(a029*a113);
  a167=(a167+a061);
  if (res[1]!=0) res[1][30]=a167;
  a169=(a024*a169);
  a167=(a029*a024);
  a167=(a043*a167);
  a169=(a169+a167);
  a167=(a013*a120);
  a169=(a169+a167);
  a169=(-a169);
  if (res[1]!=0) res[1][31]=a169;
  a171=(a024*a171);
  a013=(a013*a024);
  a013=(a043*a013);
  a171=(a171-a013);
  a029=(a029*a123);
  a171=(a171+a029);
  if (res[1]!=0) res[1][32]=a171;
  a171=(a032*a017);
  a171=(a043*a171);
  a029=(a012*a034);
  a029=(a043*a029);
  a171=(a171-a029);
  a132=(a132+a048);
  a048=(a012*a132);
  a171=(a171+a048);
  a054=(a054+a071);
  a071=(a032*a054);
  a171=(a171+a071);
  if (res[1]!=0) res[1][33]=a171;
  a171=(a032*a027);
  a171=(a043*a171);
  a071=(a012*a088);
  a071=(a043*a071);
  a171=(a171-a071);
  a138=(a138+a094);
  a094=(a012*a138);
  a171=(a171+a094);
  a145=(a145+a101);
  a101=(a032*a145);
  a171=(a171+a101);
  if (res[1]!=0) res[1][34]=a171;
  a171=(a032*a006);
  a171=(a043*a171);
  a143=(a143+a107);
  a107=(a012*a143);
  a171=(a171+a107);
  a171=(-a171);
  if (res[1]!=0) res[1][35]=a171;
  a146=(a146+a106);
  a106=(a032*a146);
  a171=(a012*a006);
  a171=(a043*a171);
  a106=(a106-a171);
  if (res[1]!=0) res[1][36]=a106;
  a106=(a032*a006);
  a106=(a043*a106);
  a153=(a153+a117);
  a117=(a012*a153);
  a106=(a106+a117);
  a106=(-a106);
  if (res[1]!=0) res[1][37]=a106;
  a152=(a152+a116);
  a116=(a032*a152);
  a106=(a012*a006);
  a106=(a043*a106);
  a116=(a116-a106);
  if (res[1]!=0) res[1][38]=a116;
  a116=(a019*a045);
  a106=(a035*a075);
  a116=(a116-a106);
  a106=(a079*a035);
  a116=(a116-a106);
  a106=(a049*a019);
  a116=(a116+a106);
  a078=(a035*a078);
  a116=(a116+a078);
  a059=(a019*a059);
  a116=(a116-a059);
  a059=(a030*a035);
  a078=(a014*a019);
  a059=(a059+a078);
  a078=(a059*a053);
  a116=(a116+a078);
  a078=casadi_sq(a035);
  a106=casadi_sq(a019);
  a078=(a078+a106);
  a078=(a078*a056);
  a116=(a116+a078);
  if (res[1]!=0) res[1][39]=a116;
  a116=(a014*a045);
  a078=(a030*a075);
  a116=(a116-a078);
  a078=(a079*a030);
  a116=(a116-a078);
  a078=(a049*a014);
  a116=(a116+a078);
  a078=(a030*a144);
  a116=(a116+a078);
  a078=(a014*a139);
  a116=(a116-a078);
  a078=casadi_sq(a030);
  a106=casadi_sq(a014);
  a078=(a078+a106);
  a078=(a078*a053);
  a116=(a116+a078);
  a059=(a059*a056);
  a116=(a116+a059);
  if (res[1]!=0) res[1][40]=a116;
  a116=(a045+a049);
  a116=(a050-a116);
  a116=(a116+a051);
  a059=(a014*a053);
  a116=(a116-a059);
  a059=(a019*a056);
  a116=(a116-a059);
  if (res[1]!=0) res[1][41]=a116;
  a116=(a075+a079);
  a116=(a067-a116);
  a116=(a116+a069);
  a059=(a030*a053);
  a116=(a116+a059);
  a059=(a035*a056);
  a116=(a116+a059);
  if (res[1]!=0) res[1][42]=a116;
  a045=(a045+a049);
  a045=(a161-a045);
  a116=(a014*a053);
  a045=(a045-a116);
  a116=(a019*a056);
  a045=(a045-a116);
  if (res[1]!=0) res[1][43]=a045;
  a075=(a075+a079);
  a075=(a168-a075);
  a045=(a030*a053);
  a075=(a075+a045);
  a045=(a035*a056);
  a075=(a075+a045);
  if (res[1]!=0) res[1][44]=a075;
  a075=(a053+a056);
  if (res[1]!=0) res[1][45]=a075;
  a075=(a053+a056);
  if (res[1]!=0) res[1][46]=a075;
  a075=(a032*a022);
  a075=(a043*a075);
  a045=(a012*a037);
  a045=(a043*a045);
  a075=(a075-a045);
  a135=(a135+a058);
  a058=(a012*a135);
  a075=(a075+a058);
  a021=(a021+a057);
  a057=(a032*a021);
  a075=(a075+a057);
  if (res[1]!=0) res[1][47]=a075;
  a075=(a032*a084);
  a075=(a043*a075);
  a057=(a012*a089);
  a057=(a043*a057);
  a075=(a075-a057);
  a140=(a140+a096);
  a096=(a012*a140);
  a075=(a075+a096);
  a093=(a093+a102);
  a102=(a032*a093);
  a075=(a075+a102);
  if (res[1]!=0) res[1][48]=a075;
  a075=(a032*a018);
  a075=(a043*a075);
  a141=(a141+a108);
  a108=(a012*a141);
  a075=(a075+a108);
  a075=(-a075);
  if (res[1]!=0) res[1][49]=a075;
  a148=(a148+a111);
  a111=(a032*a148);
  a075=(a012*a018);
  a075=(a043*a075);
  a111=(a111-a075);
  if (res[1]!=0) res[1][50]=a111;
  a111=(a032*a018);
  a111=(a043*a111);
  a154=(a154+a118);
  a118=(a012*a154);
  a111=(a111+a118);
  a111=(-a111);
  if (res[1]!=0) res[1][51]=a111;
  a156=(a156+a121);
  a032=(a032*a156);
  a012=(a012*a018);
  a043=(a043*a012);
  a032=(a032-a043);
  if (res[1]!=0) res[1][52]=a032;
  a032=(a015*a046);
  a043=(a031*a076);
  a032=(a032-a043);
  a043=(a079*a031);
  a032=(a032-a043);
  a043=(a049*a015);
  a032=(a032+a043);
  a070=(a031*a070);
  a032=(a032+a070);
  a052=(a015*a052);
  a032=(a032-a052);
  a052=(a033*a031);
  a070=(a003*a015);
  a052=(a052+a070);
  a070=(a052*a053);
  a032=(a032+a070);
  a070=casadi_sq(a031);
  a043=casadi_sq(a015);
  a070=(a070+a043);
  a070=(a070*a056);
  a032=(a032+a070);
  if (res[1]!=0) res[1][53]=a032;
  a032=(a003*a046);
  a070=(a033*a076);
  a032=(a032-a070);
  a070=(a079*a033);
  a032=(a032-a070);
  a070=(a049*a003);
  a032=(a032+a070);
  a070=(a033*a144);
  a032=(a032+a070);
  a070=(a003*a139);
  a032=(a032-a070);
  a070=casadi_sq(a033);
  a043=casadi_sq(a003);
  a070=(a070+a043);
  a070=(a070*a053);
  a032=(a032+a070);
  a052=(a052*a056);
  a032=(a032+a052);
  if (res[1]!=0) res[1][54]=a032;
  a032=(a046+a049);
  a050=(a050-a032);
  a050=(a050+a051);
  a032=(a003*a053);
  a050=(a050-a032);
  a032=(a015*a056);
  a050=(a050-a032);
  if (res[1]!=0) res[1][55]=a050;
  a050=(a076+a079);
  a067=(a067-a050);
  a067=(a067+a069);
  a050=(a033*a053);
  a067=(a067+a050);
  a050=(a031*a056);
  a067=(a067+a050);
  if (res[1]!=0) res[1][56]=a067;
  a046=(a046+a049);
  a161=(a161-a046);
  a046=(a003*a053);
  a161=(a161-a046);
  a046=(a015*a056);
  a161=(a161-a046);
  if (res[1]!=0) res[1][57]=a161;
  a076=(a076+a079);
  a168=(a168-a076);
  a076=(a033*a053);
  a168=(a168+a076);
  a076=(a031*a056);
  a168=(a168+a076);
  if (res[1]!=0) res[1][58]=a168;
  a008=(a124*a008);
  a015=(a006*a015);
  a008=(a008+a015);
  a019=(a018*a019);
  a008=(a008+a019);
  a009=(a024*a009);
  a008=(a008+a009);
  if (res[1]!=0) res[1][59]=a008;
  a170=(a025*a170);
  a003=(a006*a003);
  a170=(a170+a003);
  a014=(a018*a014);
  a170=(a170+a014);
  if (res[1]!=0) res[1][60]=a170;
  a170=(a006+a018);
  a170=(a170+a024);
  a170=(a170+a133);
  a170=(-a170);
  if (res[1]!=0) res[1][61]=a170;
  a170=(a006+a018);
  a170=(a170+a024);
  a170=(-a170);
  if (res[1]!=0) res[1][62]=a170;
  a005=(a124*a005);
  a031=(a006*a031);
  a005=(a005+a031);
  a035=(a018*a035);
  a005=(a005+a035);
  a028=(a024*a028);
  a005=(a005+a028);
  a005=(-a005);
  if (res[1]!=0) res[1][63]=a005;
  a163=(a025*a163);
  a033=(a006*a033);
  a163=(a163+a033);
  a030=(a018*a030);
  a163=(a163+a030);
  a163=(-a163);
  if (res[1]!=0) res[1][64]=a163;
  a163=(a006+a018);
  a163=(a163+a024);
  a163=(a163+a133);
  a163=(-a163);
  if (res[1]!=0) res[1][65]=a163;
  a163=(a006+a018);
  a163=(a163+a024);
  a163=(-a163);
  if (res[1]!=0) res[1][66]=a163;
  a163=cos(a002);
  a132=(a016*a132);
  a034=(a077*a034);
  a037=(a080*a037);
  a034=(a034+a037);
  a132=(a132-a034);
  a135=(a020*a135);
  a132=(a132+a135);
  a132=(a163*a132);
  a002=sin(a002);
  a017=(a047*a017);
  a022=(a055*a022);
  a017=(a017+a022);
  a054=(a016*a054);
  a017=(a017+a054);
  a021=(a020*a021);
  a017=(a017+a021);
  a017=(a002*a017);
  a132=(a132-a017);
  a017=cos(a011);
  a021=(a160*a065);
  a127=(a074*a127);
  a039=(a082*a039);
  a127=(a127+a039);
  a021=(a021-a127);
  a130=(a010*a130);
  a021=(a021+a130);
  a063=(a025*a063);
  a021=(a021+a063);
  a021=(a017*a021);
  a011=sin(a011);
  a134=(a044*a134);
  a026=(a062*a026);
  a134=(a134+a026);
  a065=(a064*a065);
  a134=(a134+a065);
  a129=(a010*a129);
  a134=(a134+a129);
  a081=(a025*a081);
  a134=(a134+a081);
  a134=(a011*a134);
  a021=(a021-a134);
  a021=(a132+a021);
  a134=cos(a004);
  a126=(a126*a133);
  a038=(a072*a038);
  a126=(a126-a038);
  a038=(a124*a133);
  a051=(a038*a051);
  a126=(a126-a051);
  a060=(a007*a060);
  a126=(a126+a060);
  a126=(a134*a126);
  a004=sin(a004);
  a023=(a040*a023);
  a128=(a128*a133);
  a023=(a023-a128);
  a128=(a124*a133);
  a069=(a128*a069);
  a023=(a023+a069);
  a036=(a007*a036);
  a023=(a023+a036);
  a023=(a004*a023);
  a126=(a126-a023);
  a021=(a021+a126);
  if (res[1]!=0) res[1][67]=a021;
  a138=(a016*a138);
  a088=(a077*a088);
  a089=(a080*a089);
  a088=(a088+a089);
  a138=(a138-a088);
  a140=(a020*a140);
  a138=(a138+a140);
  a138=(a163*a138);
  a027=(a047*a027);
  a084=(a055*a084);
  a027=(a027+a084);
  a145=(a016*a145);
  a027=(a027+a145);
  a093=(a020*a093);
  a027=(a027+a093);
  a027=(a002*a027);
  a138=(a138-a027);
  a158=(a158*a024);
  a085=(a085*a041);
  a158=(a158+a085);
  a085=(a025*a024);
  a139=(a085*a139);
  a158=(a158-a139);
  a137=(a074*a137);
  a158=(a158-a137);
  a092=(a082*a092);
  a158=(a158-a092);
  a160=(a160*a098);
  a158=(a158+a160);
  a142=(a010*a142);
  a158=(a158+a142);
  a100=(a025*a100);
  a158=(a158+a100);
  a158=(a017*a158);
  a100=(a025*a024);
  a144=(a100*a144);
  a091=(a091*a073);
  a164=(a164*a024);
  a091=(a091+a164);
  a144=(a144-a091);
  a131=(a044*a131);
  a144=(a144+a131);
  a086=(a062*a086);
  a144=(a144+a086);
  a064=(a064*a098);
  a144=(a144+a064);
  a095=(a010*a095);
  a144=(a144+a095);
  a105=(a025*a105);
  a144=(a144+a105);
  a144=(a011*a144);
  a158=(a158-a144);
  a158=(a138+a158);
  a097=(a007*a097);
  a090=(a072*a090);
  a097=(a097-a090);
  a097=(a134*a097);
  a068=(a040*a068);
  a103=(a007*a103);
  a068=(a068+a103);
  a068=(a004*a068);
  a097=(a097-a068);
  a158=(a158+a097);
  if (res[1]!=0) res[1][68]=a158;
  a158=(a047*a006);
  a097=(a055*a018);
  a158=(a158+a097);
  a158=(a002*a158);
  a143=(a016*a143);
  a141=(a020*a141);
  a143=(a143+a141);
  a143=(a163*a143);
  a158=(a158-a143);
  a136=(a044*a136);
  a143=(a062*a024);
  a136=(a136+a143);
  a136=(a011*a136);
  a143=(a085*a053);
  a147=(a010*a147);
  a143=(a143+a147);
  a110=(a025*a110);
  a143=(a143+a110);
  a143=(a017*a143);
  a136=(a136-a143);
  a136=(a158+a136);
  a143=(a124*a133);
  a143=(a143*a001);
  a087=(a040*a087);
  a143=(a143+a087);
  a143=(a004*a143);
  a038=(a038*a056);
  a109=(a007*a109);
  a038=(a038+a109);
  a038=(a134*a038);
  a143=(a143-a038);
  a136=(a136+a143);
  if (res[1]!=0) res[1][69]=a136;
  a136=(a077*a006);
  a143=(a080*a018);
  a136=(a136+a143);
  a136=(a163*a136);
  a146=(a016*a146);
  a148=(a020*a148);
  a146=(a146+a148);
  a146=(a002*a146);
  a136=(a136+a146);
  a151=(a074*a151);
  a146=(a082*a024);
  a151=(a151+a146);
  a151=(a017*a151);
  a146=(a100*a053);
  a149=(a010*a149);
  a146=(a146+a149);
  a113=(a025*a113);
  a146=(a146+a113);
  a146=(a011*a146);
  a151=(a151+a146);
  a151=(a136+a151);
  a124=(a124*a133);
  a124=(a124*a001);
  a115=(a072*a115);
  a124=(a124+a115);
  a124=(a134*a124);
  a128=(a128*a056);
  a112=(a007*a112);
  a128=(a128+a112);
  a128=(a004*a128);
  a124=(a124+a128);
  a151=(a151+a124);
  a151=(-a151);
  if (res[1]!=0) res[1][70]=a151;
  a047=(a047*a006);
  a055=(a055*a018);
  a047=(a047+a055);
  a047=(a002*a047);
  a153=(a016*a153);
  a154=(a020*a154);
  a153=(a153+a154);
  a153=(a163*a153);
  a047=(a047-a153);
  a044=(a044*a150);
  a062=(a062*a024);
  a044=(a044+a062);
  a044=(a011*a044);
  a085=(a085*a053);
  a155=(a010*a155);
  a085=(a085+a155);
  a120=(a025*a120);
  a085=(a085+a120);
  a085=(a017*a085);
  a044=(a044-a085);
  a044=(a047+a044);
  a040=(a040*a114);
  a040=(a004*a040);
  a119=(a007*a119);
  a119=(a134*a119);
  a040=(a040-a119);
  a044=(a044+a040);
  if (res[1]!=0) res[1][71]=a044;
  a077=(a077*a006);
  a080=(a080*a018);
  a077=(a077+a080);
  a163=(a163*a077);
  a016=(a016*a152);
  a020=(a020*a156);
  a016=(a016+a020);
  a002=(a002*a016);
  a163=(a163+a002);
  a074=(a074*a159);
  a082=(a082*a024);
  a074=(a074+a082);
  a017=(a017*a074);
  a100=(a100*a053);
  a010=(a010*a157);
  a100=(a100+a010);
  a025=(a025*a123);
  a100=(a100+a025);
  a011=(a011*a100);
  a017=(a017+a011);
  a017=(a163+a017);
  a072=(a072*a125);
  a134=(a134*a072);
  a007=(a007*a122);
  a004=(a004*a007);
  a134=(a134+a004);
  a017=(a017+a134);
  a017=(-a017);
  if (res[1]!=0) res[1][72]=a017;
  a017=0.;
  a134=arg[3]? arg[3][21] : 0;
  a004=-9.9999999999999995e-07;
  a007=(a004*a134);
  a122=9.9999999999999995e-07;
  a072=arg[3]? arg[3][20] : 0;
  a125=(a122*a072);
  a007=(a007+a125);
  a125=casadi_sq(a007);
  a011=arg[0]? arg[0][2] : 0;
  a100=casadi_sq(a011);
  a025=arg[0]? arg[0][3] : 0;
  a123=casadi_sq(a025);
  a100=(a100+a123);
  a123=casadi_fmax(a125,a100);
  a010=sqrt(a123);
  a157=(a134+a010);
  a157=(a157-a072);
  a053=(a017<a157);
  a074=1.3333333333333333e+00;
  a082=1.;
  a024=7.5000000000000000e-01;
  a159=-7.5000000000000000e-01;
  a002=arg[3]? arg[3][34] : 0;
  a016=casadi_sq(a002);
  a016=(a159*a016);
  a024=(a024+a016);
  a016=arg[4]? arg[4][0] : 0;
  a020=arg[3]? arg[3][35] : 0;
  a156=casadi_fmax(a016,a020);
  a152=(a024/a156);
  a077=-5.0000000000000000e-01;
  a080=pow(a123,a077);
  a018=(a080*a011);
  a006=arg[0]? arg[0][8] : 0;
  a018=(a018*a006);
  a044=(a080*a025);
  a040=arg[0]? arg[0][9] : 0;
  a044=(a044*a040);
  a018=(a018+a044);
  a044=(a152*a018);
  a044=(a082+a044);
  a119=1.0000000000000000e-300;
  a114=casadi_fmax(a119,a157);
  a085=arg[3]? arg[3][33] : 0;
  a120=pow(a114,a085);
  a155=(a072*a134);
  a062=(a072-a134);
  a155=(a155/a062);
  a150=sqrt(a155);
  a153=(a074*a150);
  a154=arg[3]? arg[3][23] : 0;
  a055=casadi_sq(a154);
  a055=(a082-a055);
  a151=arg[3]? arg[3][22] : 0;
  a055=(a055/a151);
  a124=arg[3]? arg[3][25] : 0;
  a128=casadi_sq(a124);
  a128=(a082-a128);
  a112=arg[3]? arg[3][24] : 0;
  a128=(a128/a112);
  a056=(a055+a128);
  a153=(a153/a056);
  a115=(a153*a044);
  a001=(a115*a120);
  a001=(a053?a001:0);
  a133=(a017<=a001);
  a146=(a001<=a017);
  a146=(a146+a133);
  a133=(a133/a146);
  a146=arg[3]? arg[3][36] : 0;
  a113=arg[3]? arg[3][37] : 0;
  a149=1.0000000000000000e-03;
  a148=arg[3]? arg[3][38] : 0;
  a143=(a149*a148);
  a038=casadi_fmax(a113,a143);
  a109=(a134*a000);
  a087=(a080*a011);
  a087=(a087*a040);
  a109=(a109+a087);
  a087=(a080*a025);
  a087=(a087*a006);
  a109=(a109-a087);
  a087=casadi_fabs(a109);
  a110=casadi_fmax(a038,a087);
  a147=(a146/a110);
  a141=(a147*a109);
  a097=(a087-a113);
  a148=(a148-a113);
  a097=(a097/a148);
  a068=casadi_fmax(a017,a097);
  a103=casadi_fmin(a082,a068);
  a090=(a103*a134);
  a144=(a141*a090);
  a144=(a133*a144);
  a105=(a120*a144);
  a095=(a044*a105);
  a064=(a095/a056);
  a064=(a074*a064);
  a150=(2.*a150);
  a064=(a064/a150);
  a098=(a064/a062);
  a086=(a134*a098);
  a155=(a155/a062);
  a064=(a155*a064);
  a086=(a086-a064);
  a131=(a119<=a157);
  a157=(a157<=a119);
  a157=(a157+a131);
  a131=(a131/a157);
  a157=(a085-a082);
  a157=pow(a114,a157);
  a157=(a085*a157);
  a144=(a115*a144);
  a091=(a157*a144);
  a091=(a131*a091);
  a086=(a086-a091);
  a086=(a053?a086:0);
  a007=(2.*a007);
  a164=(a100<=a125);
  a125=(a125<=a100);
  a125=(a164+a125);
  a164=(a164/a125);
  a010=(2.*a010);
  a125=(a091/a010);
  a125=(a053?a125:0);
  a100=-1.5000000000000000e+00;
  a123=pow(a123,a100);
  a123=(a077*a123);
  a105=(a153*a105);
  a073=(a152*a105);
  a142=(a040*a073);
  a142=(a025*a142);
  a073=(a006*a073);
  a073=(a011*a073);
  a142=(a142+a073);
  a142=(a053?a142:0);
  a073=casadi_fmax(a017,a001);
  a090=(a073*a090);
  a160=(a147*a090);
  a092=casadi_sign(a109);
  a137=(a017<=a097);
  a139=(a097<=a017);
  a139=(a139+a137);
  a137=(a137/a139);
  a139=(a068<=a082);
  a068=(a082<=a068);
  a068=(a068+a139);
  a139=(a139/a068);
  a068=(a141*a073);
  a041=(a068*a134);
  a041=(a139*a041);
  a041=(a137*a041);
  a027=(a041/a148);
  a093=(a038<=a087);
  a087=(a087<=a038);
  a038=(a087+a093);
  a093=(a093/a038);
  a147=(a147/a110);
  a090=(a109*a090);
  a147=(a147*a090);
  a145=(a093*a147);
  a145=(a027-a145);
  a145=(a092*a145);
  a160=(a160+a145);
  a145=(a006*a160);
  a145=(a025*a145);
  a142=(a142-a145);
  a145=(a040*a160);
  a145=(a011*a145);
  a142=(a142+a145);
  a142=(a123*a142);
  a125=(a125+a142);
  a125=(a164*a125);
  a125=(a007*a125);
  a142=(a122*a125);
  a086=(a086+a142);
  if (res[1]!=0) res[1][73]=a086;
  a086=(a080*a011);
  a142=(a146*a080);
  a142=(a142/a110);
  a145=(a142*a109);
  a084=(a103*a025);
  a140=(a145*a084);
  a086=(a086-a140);
  a086=(a133*a086);
  a140=(a120*a086);
  a088=(a044*a140);
  a089=(a088/a056);
  a089=(a074*a089);
  a089=(a089/a150);
  a021=(a089/a062);
  a126=(a134*a021);
  a089=(a155*a089);
  a126=(a126-a089);
  a086=(a115*a086);
  a023=(a157*a086);
  a023=(a131*a023);
  a126=(a126-a023);
  a126=(a053?a126:0);
  a036=(a023/a010);
  a036=(a053?a036:0);
  a069=(a073*a011);
  a084=(a073*a084);
  a060=(a109*a084);
  a051=(a060/a110);
  a081=(a146*a051);
  a069=(a069-a081);
  a140=(a153*a140);
  a081=(a152*a140);
  a129=(a040*a081);
  a129=(a025*a129);
  a129=(a053?a129:0);
  a069=(a069+a129);
  a081=(a006*a081);
  a081=(a011*a081);
  a081=(a053?a081:0);
  a069=(a069+a081);
  a081=(a142/a110);
  a081=(a081*a060);
  a060=(a093*a081);
  a129=(a145*a073);
  a129=(a129*a025);
  a129=(a139*a129);
  a129=(a137*a129);
  a065=(a129/a148);
  a060=(a060-a065);
  a060=(a092*a060);
  a142=(a142*a084);
  a060=(a060-a142);
  a142=(a006*a060);
  a142=(a025*a142);
  a069=(a069-a142);
  a142=(a040*a060);
  a142=(a011*a142);
  a069=(a069+a142);
  a069=(a123*a069);
  a036=(a036+a069);
  a036=(a164*a036);
  a036=(a007*a036);
  a069=(a122*a036);
  a126=(a126+a069);
  if (res[1]!=0) res[1][74]=a126;
  a126=(a146*a080);
  a126=(a126/a110);
  a069=(a126*a109);
  a142=(a103*a011);
  a084=(a069*a142);
  a026=(a080*a025);
  a084=(a084+a026);
  a133=(a133*a084);
  a084=(a120*a133);
  a044=(a044*a084);
  a026=(a044/a056);
  a026=(a074*a026);
  a026=(a026/a150);
  a062=(a026/a062);
  a150=(a134*a062);
  a155=(a155*a026);
  a150=(a150-a155);
  a115=(a115*a133);
  a157=(a157*a115);
  a131=(a131*a157);
  a150=(a150-a131);
  a150=(a053?a150:0);
  a010=(a131/a010);
  a010=(a053?a010:0);
  a142=(a073*a142);
  a109=(a109*a142);
  a157=(a109/a110);
  a133=(a146*a157);
  a026=(a073*a025);
  a133=(a133+a026);
  a084=(a153*a084);
  a026=(a152*a084);
  a063=(a040*a026);
  a063=(a025*a063);
  a063=(a053?a063:0);
  a133=(a133+a063);
  a026=(a006*a026);
  a026=(a011*a026);
  a026=(a053?a026:0);
  a133=(a133+a026);
  a142=(a126*a142);
  a073=(a069*a073);
  a073=(a073*a011);
  a139=(a139*a073);
  a137=(a137*a139);
  a139=(a137/a148);
  a126=(a126/a110);
  a126=(a126*a109);
  a093=(a093*a126);
  a093=(a139-a093);
  a092=(a092*a093);
  a142=(a142+a092);
  a006=(a006*a142);
  a006=(a025*a006);
  a133=(a133-a006);
  a040=(a040*a142);
  a040=(a011*a040);
  a133=(a133+a040);
  a123=(a123*a133);
  a010=(a010+a123);
  a164=(a164*a010);
  a007=(a007*a164);
  a164=(a122*a007);
  a150=(a150+a164);
  if (res[1]!=0) res[1][75]=a150;
  a068=(a068*a103);
  a064=(a053?a064:0);
  a068=(a068+a064);
  a098=(a072*a098);
  a098=(a053?a098:0);
  a068=(a068+a098);
  a091=(a053?a091:0);
  a068=(a068+a091);
  a125=(a004*a125);
  a068=(a068+a125);
  a160=(a000*a160);
  a068=(a068+a160);
  if (res[1]!=0) res[1][76]=a068;
  a021=(a072*a021);
  a089=(a089+a021);
  a089=(a089+a023);
  a089=(a053?a089:0);
  a036=(a004*a036);
  a089=(a089+a036);
  a060=(a000*a060);
  a089=(a089+a060);
  if (res[1]!=0) res[1][77]=a089;
  a072=(a072*a062);
  a155=(a155+a072);
  a155=(a155+a131);
  a155=(a053?a155:0);
  a007=(a004*a007);
  a155=(a155+a007);
  a142=(a000*a142);
  a155=(a155+a142);
  if (res[1]!=0) res[1][78]=a155;
  a055=(a055/a151);
  a056=(a153/a056);
  a095=(a056*a095);
  a155=(a055*a095);
  a155=(a053?a155:0);
  if (res[1]!=0) res[1][79]=a155;
  a088=(a056*a088);
  a155=(a055*a088);
  a155=(a053?a155:0);
  if (res[1]!=0) res[1][80]=a155;
  a056=(a056*a044);
  a055=(a055*a056);
  a055=(a053?a055:0);
  if (res[1]!=0) res[1][81]=a055;
  a154=(2.*a154);
  a055=(a095/a151);
  a055=(a154*a055);
  a055=(a053?a055:0);
  if (res[1]!=0) res[1][82]=a055;
  a055=(a088/a151);
  a055=(a154*a055);
  a055=(a053?a055:0);
  if (res[1]!=0) res[1][83]=a055;
  a151=(a056/a151);
  a154=(a154*a151);
  a154=(a053?a154:0);
  if (res[1]!=0) res[1][84]=a154;
  a128=(a128/a112);
  a154=(a128*a095);
  a154=(a053?a154:0);
  if (res[1]!=0) res[1][85]=a154;
  a154=(a128*a088);
  a154=(a053?a154:0);
  if (res[1]!=0) res[1][86]=a154;
  a128=(a128*a056);
  a128=(a053?a128:0);
  if (res[1]!=0) res[1][87]=a128;
  a124=(2.*a124);
  a095=(a095/a112);
  a095=(a124*a095);
  a095=(a053?a095:0);
  if (res[1]!=0) res[1][88]=a095;
  a088=(a088/a112);
  a088=(a124*a088);
  a088=(a053?a088:0);
  if (res[1]!=0) res[1][89]=a088;
  a056=(a056/a112);
  a124=(a124*a056);
  a124=(a053?a124:0);
  if (res[1]!=0) res[1][90]=a124;
  a124=arg[3]? arg[3][27] : 0;
  a056=(a004*a124);
  a112=arg[3]? arg[3][26] : 0;
  a088=(a122*a112);
  a056=(a056+a088);
  a088=casadi_sq(a056);
  a095=arg[0]? arg[0][4] : 0;
  a128=casadi_sq(a095);
  a154=arg[0]? arg[0][5] : 0;
  a151=casadi_sq(a154);
  a128=(a128+a151);
  a151=casadi_fmax(a088,a128);
  a055=sqrt(a151);
  a044=(a124+a055);
  a044=(a044-a112);
  a155=(a017<a044);
  a142=(a112*a124);
  a007=(a112-a124);
  a142=(a142/a007);
  a131=(a142/a007);
  a072=arg[4]? arg[4][1] : 0;
  a062=casadi_fmax(a072,a020);
  a024=(a024/a062);
  a089=pow(a151,a077);
  a060=(a089*a095);
  a036=arg[0]? arg[0][10] : 0;
  a060=(a060*a036);
  a023=(a089*a154);
  a021=arg[0]? arg[0][11] : 0;
  a023=(a023*a021);
  a060=(a060+a023);
  a023=(a024*a060);
  a023=(a082+a023);
  a068=casadi_fmax(a119,a044);
  a160=pow(a068,a085);
  a142=sqrt(a142);
  a125=(a074*a142);
  a091=arg[3]? arg[3][29] : 0;
  a098=casadi_sq(a091);
  a098=(a082-a098);
  a064=arg[3]? arg[3][28] : 0;
  a098=(a098/a064);
  a150=arg[3]? arg[3][31] : 0;
  a164=casadi_sq(a150);
  a164=(a082-a164);
  a010=arg[3]? arg[3][30] : 0;
  a164=(a164/a010);
  a123=(a098+a164);
  a125=(a125/a123);
  a133=(a125*a023);
  a040=(a133*a160);
  a040=(a155?a040:0);
  a006=(a017<=a040);
  a092=(a040<=a017);
  a092=(a092+a006);
  a006=(a006/a092);
  a092=casadi_fmax(a113,a143);
  a093=(a112*a000);
  a109=(a124*a042);
  a093=(a093-a109);
  a109=(a089*a154);
  a109=(a109*a036);
  a093=(a093+a109);
  a109=(a089*a095);
  a109=(a109*a021);
  a093=(a093-a109);
  a109=casadi_fabs(a093);
  a073=casadi_fmax(a092,a109);
  a026=(a146/a073);
  a063=(a124*a042);
  a130=(a112*a000);
  a063=(a063-a130);
  a130=(a089*a095);
  a130=(a130*a021);
  a063=(a063+a130);
  a130=(a089*a154);
  a130=(a130*a036);
  a063=(a063-a130);
  a130=(a026*a063);
  a127=(a109-a113);
  a127=(a127/a148);
  a039=casadi_fmax(a017,a127);
  a054=casadi_fmin(a082,a039);
  a022=(a124-a112);
  a135=(a054*a022);
  a034=(a130*a135);
  a034=(a006*a034);
  a037=(a160*a034);
  a030=(a023*a037);
  a033=(a030/a123);
  a033=(a074*a033);
  a142=(2.*a142);
  a033=(a033/a142);
  a005=(a131*a033);
  a028=(-a005);
  a028=(a155?a028:0);
  a035=casadi_fmax(a017,a040);
  a031=(a130*a035);
  a170=(a031*a054);
  a028=(a028-a170);
  a033=(a033/a007);
  a014=(a124*a033);
  a014=(a155?a014:0);
  a028=(a028+a014);
  a014=(a119<=a044);
  a044=(a044<=a119);
  a044=(a044+a014);
  a014=(a014/a044);
  a044=(a085-a082);
  a044=pow(a068,a044);
  a085=(a085*a044);
  a034=(a133*a034);
  a044=(a085*a034);
  a044=(a014*a044);
  a119=(-a044);
  a119=(a155?a119:0);
  a028=(a028+a119);
  a135=(a035*a135);
  a119=(a026*a135);
  a003=(a000*a119);
  a028=(a028-a003);
  a056=(2.*a056);
  a003=(a128<=a088);
  a088=(a088<=a128);
  a088=(a003+a088);
  a003=(a003/a088);
  a055=(2.*a055);
  a088=(a044/a055);
  a088=(a155?a088:0);
  a151=pow(a151,a100);
  a077=(a077*a151);
  a037=(a125*a037);
  a151=(a024*a037);
  a100=(a021*a151);
  a100=(a154*a100);
  a151=(a036*a151);
  a151=(a095*a151);
  a100=(a100+a151);
  a100=(a155?a100:0);
  a151=(a036*a119);
  a151=(a154*a151);
  a100=(a100-a151);
  a151=(a021*a119);
  a151=(a095*a151);
  a100=(a100+a151);
  a093=casadi_sign(a093);
  a151=(a017<=a127);
  a128=(a127<=a017);
  a128=(a128+a151);
  a151=(a151/a128);
  a128=(a039<=a082);
  a082=(a082<=a039);
  a082=(a082+a128);
  a128=(a128/a082);
  a022=(a031*a022);
  a022=(a128*a022);
  a022=(a151*a022);
  a082=(a022/a148);
  a039=(a092<=a109);
  a109=(a109<=a092);
  a092=(a109+a039);
  a039=(a039/a092);
  a008=(a026/a073);
  a135=(a063*a135);
  a009=(a008*a135);
  a019=(a039*a009);
  a019=(a082-a019);
  a019=(a093*a019);
  a015=(a021*a019);
  a015=(a095*a015);
  a100=(a100-a015);
  a015=(a036*a019);
  a015=(a154*a015);
  a100=(a100+a015);
  a100=(a077*a100);
  a088=(a088+a100);
  a088=(a003*a088);
  a088=(a056*a088);
  a100=(a122*a088);
  a028=(a028+a100);
  a100=(a000*a019);
  a028=(a028+a100);
  if (res[1]!=0) res[1][91]=a028;
  a028=(a054*a124);
  a100=(a130*a028);
  a100=(a006*a100);
  a015=(a160*a100);
  a168=(a023*a015);
  a076=(a168/a123);
  a076=(a074*a076);
  a076=(a076/a142);
  a079=(a076/a007);
  a161=(a124*a079);
  a076=(a131*a076);
  a161=(a161-a076);
  a100=(a133*a100);
  a046=(a085*a100);
  a046=(a014*a046);
  a161=(a161-a046);
  a161=(a155?a161:0);
  a028=(a035*a028);
  a026=(a026*a028);
  a049=(a000*a026);
  a161=(a161-a049);
  a049=(a046/a055);
  a049=(a155?a049:0);
  a015=(a125*a015);
  a067=(a024*a015);
  a050=(a021*a067);
  a050=(a154*a050);
  a067=(a036*a067);
  a067=(a095*a067);
  a050=(a050+a067);
  a050=(a155?a050:0);
  a067=(a036*a026);
  a067=(a154*a067);
  a050=(a050-a067);
  a067=(a021*a026);
  a067=(a095*a067);
  a050=(a050+a067);
  a031=(a031*a124);
  a031=(a128*a031);
  a031=(a151*a031);
  a067=(a031/a148);
  a028=(a063*a028);
  a008=(a008*a028);
  a032=(a039*a008);
  a032=(a067-a032);
  a032=(a093*a032);
  a052=(a021*a032);
  a052=(a095*a052);
  a050=(a050-a052);
  a052=(a036*a032);
  a052=(a154*a052);
  a050=(a050+a052);
  a050=(a077*a050);
  a049=(a049+a050);
  a049=(a003*a049);
  a049=(a056*a049);
  a050=(a122*a049);
  a161=(a161+a050);
  a050=(a000*a032);
  a161=(a161+a050);
  if (res[1]!=0) res[1][92]=a161;
  a161=(a089*a095);
  a050=(a146*a089);
  a050=(a050/a073);
  a052=(a050*a063);
  a070=(a054*a154);
  a043=(a052*a070);
  a161=(a161-a043);
  a161=(a006*a161);
  a043=(a160*a161);
  a012=(a023*a043);
  a121=(a012/a123);
  a121=(a074*a121);
  a121=(a121/a142);
  a111=(a121/a007);
  a118=(a124*a111);
  a121=(a131*a121);
  a118=(a118-a121);
  a161=(a133*a161);
  a075=(a085*a161);
  a075=(a014*a075);
  a118=(a118-a075);
  a118=(a155?a118:0);
  a070=(a035*a070);
  a108=(a050*a070);
  a102=(a000*a108);
  a118=(a118+a102);
  a102=(a075/a055);
  a102=(a155?a102:0);
  a096=(a035*a095);
  a070=(a063*a070);
  a057=(a070/a073);
  a058=(a146*a057);
  a096=(a096-a058);
  a043=(a125*a043);
  a058=(a024*a043);
  a045=(a021*a058);
  a045=(a154*a045);
  a045=(a155?a045:0);
  a096=(a096+a045);
  a058=(a036*a058);
  a058=(a095*a058);
  a058=(a155?a058:0);
  a096=(a096+a058);
  a058=(a036*a108);
  a058=(a154*a058);
  a096=(a096+a058);
  a058=(a021*a108);
  a058=(a095*a058);
  a096=(a096-a058);
  a050=(a050/a073);
  a050=(a050*a070);
  a070=(a039*a050);
  a058=(a052*a035);
  a058=(a058*a154);
  a058=(a128*a058);
  a058=(a151*a058);
  a045=(a058/a148);
  a070=(a070-a045);
  a070=(a093*a070);
  a116=(a021*a070);
  a116=(a095*a116);
  a096=(a096-a116);
  a116=(a036*a070);
  a116=(a154*a116);
  a096=(a096+a116);
  a096=(a077*a096);
  a102=(a102+a096);
  a102=(a003*a102);
  a102=(a056*a102);
  a096=(a122*a102);
  a118=(a118+a096);
  a096=(a000*a070);
  a118=(a118+a096);
  if (res[1]!=0) res[1][93]=a118;
  a118=(a146*a089);
  a118=(a118/a073);
  a096=(a118*a063);
  a116=(a054*a095);
  a059=(a096*a116);
  a078=(a089*a154);
  a059=(a059+a078);
  a006=(a006*a059);
  a059=(a160*a006);
  a023=(a023*a059);
  a078=(a023/a123);
  a074=(a074*a078);
  a074=(a074/a142);
  a007=(a074/a007);
  a142=(a124*a007);
  a131=(a131*a074);
  a142=(a142-a131);
  a133=(a133*a006);
  a085=(a085*a133);
  a014=(a014*a085);
  a142=(a142-a014);
  a142=(a155?a142:0);
  a116=(a035*a116);
  a085=(a118*a116);
  a006=(a000*a085);
  a142=(a142-a006);
  a055=(a014/a055);
  a055=(a155?a055:0);
  a063=(a063*a116);
  a116=(a063/a073);
  a146=(a146*a116);
  a006=(a035*a154);
  a146=(a146+a006);
  a059=(a125*a059);
  a006=(a024*a059);
  a074=(a021*a006);
  a074=(a154*a074);
  a074=(a155?a074:0);
  a146=(a146+a074);
  a006=(a036*a006);
  a006=(a095*a006);
  a006=(a155?a006:0);
  a146=(a146+a006);
  a006=(a036*a085);
  a006=(a154*a006);
  a146=(a146-a006);
  a006=(a021*a085);
  a006=(a095*a006);
  a146=(a146+a006);
  a035=(a096*a035);
  a035=(a035*a095);
  a128=(a128*a035);
  a151=(a151*a128);
  a128=(a151/a148);
  a118=(a118/a073);
  a118=(a118*a063);
  a039=(a039*a118);
  a039=(a128-a039);
  a093=(a093*a039);
  a021=(a021*a093);
  a021=(a095*a021);
  a146=(a146-a021);
  a036=(a036*a093);
  a036=(a154*a036);
  a146=(a146+a036);
  a077=(a077*a146);
  a055=(a055+a077);
  a003=(a003*a055);
  a056=(a056*a003);
  a122=(a122*a056);
  a142=(a142+a122);
  a000=(a000*a093);
  a142=(a142+a000);
  if (res[1]!=0) res[1][94]=a142;
  a005=(a155?a005:0);
  a005=(a170+a005);
  a033=(a112*a033);
  a033=(a155?a033:0);
  a005=(a005+a033);
  a044=(a155?a044:0);
  a005=(a005+a044);
  a119=(a042*a119);
  a005=(a005+a119);
  a088=(a004*a088);
  a005=(a005+a088);
  a019=(a042*a019);
  a005=(a005-a019);
  if (res[1]!=0) res[1][95]=a005;
  a076=(a155?a076:0);
  a170=(a170+a076);
  a079=(a112*a079);
  a079=(a155?a079:0);
  a170=(a170+a079);
  a046=(a155?a046:0);
  a170=(a170+a046);
  a026=(a042*a026);
  a170=(a170+a026);
  a049=(a004*a049);
  a170=(a170+a049);
  a032=(a042*a032);
  a170=(a170-a032);
  if (res[1]!=0) res[1][96]=a170;
  a111=(a112*a111);
  a121=(a121+a111);
  a121=(a121+a075);
  a121=(a155?a121:0);
  a108=(a042*a108);
  a121=(a121-a108);
  a102=(a004*a102);
  a121=(a121+a102);
  a070=(a042*a070);
  a121=(a121-a070);
  if (res[1]!=0) res[1][97]=a121;
  a007=(a112*a007);
  a131=(a131+a007);
  a131=(a131+a014);
  a131=(a155?a131:0);
  a085=(a042*a085);
  a131=(a131+a085);
  a004=(a004*a056);
  a131=(a131+a004);
  a042=(a042*a093);
  a131=(a131-a042);
  if (res[1]!=0) res[1][98]=a131;
  a098=(a098/a064);
  a123=(a125/a123);
  a030=(a123*a030);
  a131=(a098*a030);
  a131=(a155?a131:0);
  if (res[1]!=0) res[1][99]=a131;
  a168=(a123*a168);
  a131=(a098*a168);
  a131=(a155?a131:0);
  if (res[1]!=0) res[1][100]=a131;
  a012=(a123*a012);
  a131=(a098*a012);
  a131=(a155?a131:0);
  if (res[1]!=0) res[1][101]=a131;
  a123=(a123*a023);
  a098=(a098*a123);
  a098=(a155?a098:0);
  if (res[1]!=0) res[1][102]=a098;
  a091=(2.*a091);
  a098=(a030/a064);
  a098=(a091*a098);
  a098=(a155?a098:0);
  if (res[1]!=0) res[1][103]=a098;
  a098=(a168/a064);
  a098=(a091*a098);
  a098=(a155?a098:0);
  if (res[1]!=0) res[1][104]=a098;
  a098=(a012/a064);
  a098=(a091*a098);
  a098=(a155?a098:0);
  if (res[1]!=0) res[1][105]=a098;
  a064=(a123/a064);
  a091=(a091*a064);
  a091=(a155?a091:0);
  if (res[1]!=0) res[1][106]=a091;
  a164=(a164/a010);
  a091=(a164*a030);
  a091=(a155?a091:0);
  if (res[1]!=0) res[1][107]=a091;
  a091=(a164*a168);
  a091=(a155?a091:0);
  if (res[1]!=0) res[1][108]=a091;
  a091=(a164*a012);
  a091=(a155?a091:0);
  if (res[1]!=0) res[1][109]=a091;
  a164=(a164*a123);
  a164=(a155?a164:0);
  if (res[1]!=0) res[1][110]=a164;
  a150=(2.*a150);
  a030=(a030/a010);
  a030=(a150*a030);
  a030=(a155?a030:0);
  if (res[1]!=0) res[1][111]=a030;
  a168=(a168/a010);
  a168=(a150*a168);
  a168=(a155?a168:0);
  if (res[1]!=0) res[1][112]=a168;
  a012=(a012/a010);
  a012=(a150*a012);
  a012=(a155?a012:0);
  if (res[1]!=0) res[1][113]=a012;
  a123=(a123/a010);
  a150=(a150*a123);
  a150=(a155?a150:0);
  if (res[1]!=0) res[1][114]=a150;
  if (res[1]!=0) res[1][115]=a132;
  if (res[1]!=0) res[1][116]=a138;
  if (res[1]!=0) res[1][117]=a158;
  a136=(-a136);
  if (res[1]!=0) res[1][118]=a136;
  if (res[1]!=0) res[1][119]=a047;
  a163=(-a163);
  if (res[1]!=0) res[1][120]=a163;
  a068=log(a068);
  a068=(a068*a160);
  a034=(a068*a034);
  a034=(a155?a034:0);
  a114=log(a114);
  a114=(a114*a120);
  a144=(a114*a144);
  a144=(a053?a144:0);
  a034=(a034+a144);
  if (res[1]!=0) res[1][121]=a034;
  a100=(a068*a100);
  a100=(a155?a100:0);
  if (res[1]!=0) res[1][122]=a100;
  a086=(a114*a086);
  a086=(a053?a086:0);
  if (res[1]!=0) res[1][123]=a086;
  a114=(a114*a115);
  a114=(a053?a114:0);
  if (res[1]!=0) res[1][124]=a114;
  a161=(a068*a161);
  a161=(a155?a161:0);
  if (res[1]!=0) res[1][125]=a161;
  a068=(a068*a133);
  a068=(a155?a068:0);
  if (res[1]!=0) res[1][126]=a068;
  a002=(2.*a002);
  a037=(a060*a037);
  a068=(a037/a062);
  a068=(a155?a068:0);
  a105=(a018*a105);
  a133=(a105/a156);
  a133=(a053?a133:0);
  a068=(a068+a133);
  a068=(a159*a068);
  a068=(a002*a068);
  if (res[1]!=0) res[1][127]=a068;
  a015=(a060*a015);
  a068=(a015/a062);
  a068=(a159*a068);
  a068=(a002*a068);
  a068=(a155?a068:0);
  if (res[1]!=0) res[1][128]=a068;
  a140=(a018*a140);
  a068=(a140/a156);
  a068=(a159*a068);
  a068=(a002*a068);
  a068=(a053?a068:0);
  if (res[1]!=0) res[1][129]=a068;
  a084=(a018*a084);
  a068=(a084/a156);
  a068=(a159*a068);
  a068=(a002*a068);
  a068=(a053?a068:0);
  if (res[1]!=0) res[1][130]=a068;
  a043=(a060*a043);
  a068=(a043/a062);
  a068=(a159*a068);
  a068=(a002*a068);
  a068=(a155?a068:0);
  if (res[1]!=0) res[1][131]=a068;
  a059=(a060*a059);
  a068=(a059/a062);
  a159=(a159*a068);
  a002=(a002*a159);
  a002=(a155?a002:0);
  if (res[1]!=0) res[1][132]=a002;
  a002=(a072<=a020);
  a159=(a020<=a072);
  a159=(a159+a002);
  a002=(a002/a159);
  a159=(a024/a062);
  a037=(a159*a037);
  a037=(a002*a037);
  a037=(-a037);
  a037=(a155?a037:0);
  a068=(a016<=a020);
  a133=(a020<=a016);
  a133=(a133+a068);
  a068=(a068/a133);
  a133=(a152/a156);
  a105=(a133*a105);
  a105=(a068*a105);
  a105=(-a105);
  a105=(a053?a105:0);
  a037=(a037+a105);
  if (res[1]!=0) res[1][133]=a037;
  a015=(a159*a015);
  a015=(a002*a015);
  a015=(-a015);
  a015=(a155?a015:0);
  if (res[1]!=0) res[1][134]=a015;
  a140=(a133*a140);
  a140=(a068*a140);
  a140=(-a140);
  a140=(a053?a140:0);
  if (res[1]!=0) res[1][135]=a140;
  a133=(a133*a084);
  a068=(a068*a133);
  a068=(-a068);
  a068=(a053?a068:0);
  if (res[1]!=0) res[1][136]=a068;
  a043=(a159*a043);
  a043=(a002*a043);
  a043=(-a043);
  a043=(a155?a043:0);
  if (res[1]!=0) res[1][137]=a043;
  a159=(a159*a059);
  a002=(a002*a159);
  a002=(-a002);
  a002=(a155?a002:0);
  if (res[1]!=0) res[1][138]=a002;
  a135=(a135/a073);
  a090=(a090/a110);
  a135=(a135+a090);
  if (res[1]!=0) res[1][139]=a135;
  a028=(a028/a073);
  if (res[1]!=0) res[1][140]=a028;
  a051=(a080*a051);
  a051=(-a051);
  if (res[1]!=0) res[1][141]=a051;
  a157=(a080*a157);
  if (res[1]!=0) res[1][142]=a157;
  a057=(a089*a057);
  a057=(-a057);
  if (res[1]!=0) res[1][143]=a057;
  a116=(a089*a116);
  if (res[1]!=0) res[1][144]=a116;
  a127=(a127/a148);
  a022=(a127*a022);
  a097=(a097/a148);
  a041=(a097*a041);
  a022=(a022+a041);
  a041=(a143<=a113);
  a148=(a113<=a143);
  a116=(a041+a148);
  a041=(a041/a116);
  a109=(a109/a092);
  a009=(a109*a009);
  a092=(a041*a009);
  a082=(a082+a092);
  a082=(a022-a082);
  a082=(a082-a027);
  a027=(a143<=a113);
  a113=(a113<=a143);
  a143=(a027+a113);
  a027=(a027/a143);
  a087=(a087/a038);
  a147=(a087*a147);
  a038=(a027*a147);
  a082=(a082-a038);
  if (res[1]!=0) res[1][145]=a082;
  a031=(a127*a031);
  a008=(a109*a008);
  a082=(a041*a008);
  a067=(a067+a082);
  a067=(a031-a067);
  if (res[1]!=0) res[1][146]=a067;
  a129=(a097*a129);
  a065=(a065-a129);
  a081=(a087*a081);
  a067=(a027*a081);
  a065=(a065+a067);
  if (res[1]!=0) res[1][147]=a065;
  a097=(a097*a137);
  a139=(a097-a139);
  a087=(a087*a126);
  a027=(a027*a087);
  a139=(a139-a027);
  if (res[1]!=0) res[1][148]=a139;
  a050=(a109*a050);
  a139=(a041*a050);
  a045=(a045+a139);
  a058=(a127*a058);
  a045=(a045-a058);
  if (res[1]!=0) res[1][149]=a045;
  a127=(a127*a151);
  a109=(a109*a118);
  a041=(a041*a109);
  a128=(a128+a041);
  a128=(a127-a128);
  if (res[1]!=0) res[1][150]=a128;
  a148=(a148/a116);
  a009=(a148*a009);
  a113=(a113/a143);
  a147=(a113*a147);
  a009=(a009+a147);
  a009=(a149*a009);
  a022=(a022+a009);
  a022=(-a022);
  if (res[1]!=0) res[1][151]=a022;
  a008=(a148*a008);
  a008=(a149*a008);
  a031=(a031+a008);
  a031=(-a031);
  if (res[1]!=0) res[1][152]=a031;
  a081=(a113*a081);
  a081=(a149*a081);
  a129=(a129+a081);
  if (res[1]!=0) res[1][153]=a129;
  a113=(a113*a087);
  a113=(a149*a113);
  a097=(a097+a113);
  a097=(-a097);
  if (res[1]!=0) res[1][154]=a097;
  a050=(a148*a050);
  a050=(a149*a050);
  a058=(a058+a050);
  if (res[1]!=0) res[1][155]=a058;
  a148=(a148*a109);
  a149=(a149*a148);
  a127=(a127+a149);
  a127=(-a127);
  if (res[1]!=0) res[1][156]=a127;
  a127=(a017<=a001);
  a001=(a001<=a017);
  a001=(a001+a127);
  a127=(a127/a001);
  a152=(a152/a156);
  a156=(a020<=a016);
  a016=(a016<=a020);
  a016=(a156+a016);
  a156=(a156/a016);
  a152=(a152*a156);
  a018=(a018*a152);
  a153=(a153*a018);
  a120=(a120*a153);
  a127=(a127*a120);
  a141=(a141*a127);
  a141=(a103*a141);
  a134=(a134*a141);
  a134=(-a134);
  a134=(a053?a134:0);
  if (res[2]!=0) res[2][0]=a134;
  a134=(a080*a127);
  a134=(a011*a134);
  a145=(a145*a127);
  a145=(a103*a145);
  a145=(a025*a145);
  a134=(a134-a145);
  a134=(-a134);
  a134=(a053?a134:0);
  if (res[2]!=0) res[2][1]=a134;
  a080=(a080*a127);
  a025=(a025*a080);
  a069=(a069*a127);
  a103=(a103*a069);
  a011=(a011*a103);
  a025=(a025+a011);
  a025=(-a025);
  a053=(a053?a025:0);
  if (res[2]!=0) res[2][2]=a053;
  a053=(a017<=a040);
  a040=(a040<=a017);
  a040=(a040+a053);
  a053=(a053/a040);
  a024=(a024/a062);
  a062=(a020<=a072);
  a072=(a072<=a020);
  a072=(a062+a072);
  a062=(a062/a072);
  a024=(a024*a062);
  a060=(a060*a024);
  a125=(a125*a060);
  a160=(a160*a125);
  a053=(a053*a160);
  a130=(a130*a053);
  a130=(a054*a130);
  a124=(a124*a130);
  a112=(a112*a130);
  a112=(a124-a112);
  a112=(-a112);
  a112=(a155?a112:0);
  if (res[2]!=0) res[2][3]=a112;
  a124=(-a124);
  a124=(a155?a124:0);
  if (res[2]!=0) res[2][4]=a124;
  a124=(a089*a053);
  a124=(a095*a124);
  a052=(a052*a053);
  a052=(a054*a052);
  a052=(a154*a052);
  a124=(a124-a052);
  a124=(-a124);
  a124=(a155?a124:0);
  if (res[2]!=0) res[2][5]=a124;
  a089=(a089*a053);
  a154=(a154*a089);
  a096=(a096*a053);
  a054=(a054*a096);
  a095=(a095*a054);
  a154=(a154+a095);
  a154=(-a154);
  a155=(a155?a154:0);
  if (res[2]!=0) res[2][6]=a155;
  return 0;
}

/* jac_forward_dynamics:(x[12],tau[2],p[39],v_imp[2],out_xdot[12x1,0nz])->(jac_xdot_x[12x12,78nz],jac_xdot_tau[12x2,12nz],jac_xdot_p[12x39,234nz],jac_xdot_v_imp[12x2,12nz]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real **res1=res+4, *rr, *w00=w+173, *w01=w+179, *w02=w+185, *w03=w+197, *w05=w+199, *w07=w+201, *w08=w+237, *w09=w+289, *w10=w+361, *w11=w+433;
  casadi_real *w12=w+511, *w14=w+589, *w15=w+591, *w16=w+748, *w17=w+755, *w18=w+767, *w19=w+1001;
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
  if (casadi_f4(arg1, res1, iw, w, 0)) return 1;
  casadi_densify(w08, casadi_s8, w09, 0);
  rr = w09;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 12, casadi_s6, lt, d, casadi_s7, w);
  }
  for (i=0, rr=w09, cs=w09; i<72; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w10, cs=w09; i<12; ++i) for (j=0; j<6; ++j) rr[i+j*12] = *cs++;
  rr=w11;
  for (i=0, cs=w00; i<6; ++i) *rr++ = *cs++;
  for (i=0, cs=w10; i<72; ++i) *rr++ = *cs++;
  casadi_trans(w11,casadi_s10, w12, casadi_s9, iw);
  casadi_copy(w12, 78, res[0]);
  arg1[0]=wr02;
  arg1[1]=w01;
  arg1[2]=w03;
  arg1[3]=wr04;
  arg1[4]=w05;
  res1[0]=w14;
  res1[1]=w15;
  res1[2]=w16;
  if (casadi_f5(arg1, res1, iw, w, 0)) return 1;
  casadi_densify(w14, casadi_s11, w02, 0);
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
  casadi_densify(w15, casadi_s14, w18, 0);
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
  casadi_densify(w16, casadi_s17, w17, 0);
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
  if (sz_res) *sz_res = 7;
  if (sz_iw) *sz_iw = 40;
  if (sz_w) *sz_w = 1235;
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 10*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 7*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 40*sizeof(casadi_int);
  if (sz_w) *sz_w = 1235*sizeof(casadi_real);
  return 0;
}

/* jac_state:(x[12],tau[2],p[39],v_imp[2])->(jac_xdot_x[12x12,78nz]) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real **res1=res+1, *rr, *w00=w+113, *w01=w+119, *w03=w+125, *w05=w+127, *w07=w+129, *w08=w+165, *w09=w+217, *w10=w+289, *w11=w+361, *w12=w+439;
  const casadi_real **arg1=arg+4, *cs, *ss, *wr02, *wr04, *wr06;
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
  if (casadi_f4(arg1, res1, iw, w, 0)) return 1;
  casadi_densify(w08, casadi_s8, w09, 0);
  rr = w09;
  ss = w07;
  {
    casadi_real lt[15], d[6], w[6];
    casadi_ldl(casadi_s5, ss, casadi_s6, lt, d, casadi_s7, w);
    casadi_ldl_solve(rr, 12, casadi_s6, lt, d, casadi_s7, w);
  }
  for (i=0, rr=w09, cs=w09; i<72; ++i) *rr++ = (- *cs++ );
  for (i=0, rr=w10, cs=w09; i<12; ++i) for (j=0; j<6; ++j) rr[i+j*12] = *cs++;
  rr=w11;
  for (i=0, cs=w00; i<6; ++i) *rr++ = *cs++;
  for (i=0, cs=w10; i<72; ++i) *rr++ = *cs++;
  casadi_trans(w11,casadi_s10, w12, casadi_s9, iw);
  casadi_copy(w12, 78, res[0]);
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_state(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f6(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int jac_state_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void jac_state_release(int mem) {
}

CASADI_SYMBOL_EXPORT void jac_state_incref(void) {
}

CASADI_SYMBOL_EXPORT void jac_state_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int jac_state_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int jac_state_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real jac_state_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jac_state_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "tau";
    case 2: return "p";
    case 3: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jac_state_name_out(casadi_int i) {
  switch (i) {
    case 0: return "jac_xdot_x";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_state_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    case 2: return casadi_s1;
    case 3: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jac_state_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s9;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int jac_state_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 13;
  if (sz_w) *sz_w = 517;
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_state_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 13*sizeof(casadi_int);
  if (sz_w) *sz_w = 517*sizeof(casadi_real);
  return 0;
}

/* contact:(x[12],p[39],v_imp[2])->(delta[2],delta_dot[2],v_t[2],f_n[2],f_t[2],f_x[2],f_y[2],dissipation[2]) */
static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  return casadi_f7(arg, res, iw, w, mem);
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
static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  return casadi_f8(arg, res, iw, w, mem);
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
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  return casadi_f9(arg, res, iw, w, mem);
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
static int casadi_f10(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  return casadi_f10(arg, res, iw, w, mem);
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
static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real *qr_beta, *qr_r, *qr_v, *qr_w, **res1=res+2, *rr, *w00=w+574, *w01=w+586, w02, *w04=w+604, *w05=w+610, *w06=w+664;
  casadi_real *w07=w+682, *w08=w+1006, *w09=w+1330, *w11=w+1332, *w12=w+1334, *w13=w+1412, *w14=w+1448, w15, *w17=w+1772, *w18=w+1808, *w19=w+1820, *w20=w+1832;
  casadi_real *w21=w+1844, *w22=w+1880, *w23=w+1898, *w24=w+1916, *w25=w+1934;
  const casadi_real **arg1=arg+5, *cr, *cs, *ct, *ss, *wr00, *wr03, *wr07, *wr08, *wr10, *wr16;
  wr00 = arg[0] ? arg[0] : casadi_zeros;
  casadi_clear(w01, 18);
  w02 = arg[2] ? arg[2][0] : 0;
  wr03 = casadi_c0;
  casadi_fill(w04, 6, 1.);
  casadi_kron_dense_sparse(wr03, 3, 3, w04, casadi_s21, w05);
  for (i=0, rr=w05, cs=w05; i<54; ++i) (*rr++)  = (w02*(*cs++));
  casadi_clear(w06, 18);
  wr07 = casadi_c1;
  wr08 = casadi_c1;
  casadi_copy(arg[1], 6, w04);
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  wr10 = arg[3] ? arg[3] : casadi_zeros;
  casadi_copy(arg[4], 2, w11);
  arg1[0]=wr00;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w12;
  if (casadi_f6(arg1, res1, iw, w, 0)) return 1;
  for (rr=w13, cs=w12+0; cs!=w12+42; cs+=7) for (ct=cs+37; ct!=cs+43; ct+=1) *rr++ = *ct;
  casadi_kron_dense(wr03, 3, 3, w13, 6, 6, w14);
  for (i=0, rr=w14, cs=w14; i<324; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w08, cr=wr08, cs=w14; i<324; ++i) (*rr++)  = ((*cr++)-(*cs++));
  w15 = casadi_sq( w02 );
  wr16 = casadi_c2;
  for (rr=w13, cs=w12+0; cs!=w12+36; cs+=1) *rr++ = *cs;
  casadi_kron_dense(wr16, 3, 3, w13, 6, 6, w14);
  for (i=0, rr=w14, cs=w14; i<324; ++i) (*rr++)  = (w15*(*cs++));
  for (i=0, rr=w08, cs=w14; i<324; ++i) (*rr++) -= (*cs++);
  rr = w07;
  ss = w08;
  casadi_copy(wr07, 324, rr);
  qr_v = w;
  qr_r = w+171;
  qr_beta = w+342;
  qr_w = w+360;
  casadi_qr(casadi_s23, ss, qr_w, casadi_s24, qr_v, casadi_s25, qr_r, qr_beta, casadi_s22, casadi_s22);
  casadi_qr_solve(rr, 18, 0, casadi_s24, qr_v, casadi_s25, qr_r, qr_beta, casadi_s22, casadi_s22, qr_w);
  casadi_clear(w17, 36);
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w18;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w20;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w21;
  for (i=0, cs=w18; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w20; i<12; ++i) *rr++ = *cs++;
  wr16 = casadi_c3;
  casadi_mtimes_dense(w21, 12, 3, wr16, 3, w17, 0);
  for (i=0, rr=w17, cs=w17; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w17, cs=w17; i<36; ++i) *rr++ = (- *cs++ );
  for (rr=w22, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w23, 18);
  casadi_kron_dense(wr03, 3, 3, w13, 6, 6, w08);
  for (i=0, rr=w08, cs=w08; i<324; ++i) (*rr++)  = (w02*(*cs++));
  for (rr=w24, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w24, 1, w23, 0);
  for (i=0, rr=w22, cs=w23; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w22, 1, w06, 0);
  for (i=0, rr=w06, cs=w06; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w06, casadi_s26, w01, casadi_s26, w, 0);
  for (i=0, rr=w01, cs=w24; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w24, cs=w01; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w01, cs=w06; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w17;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w01; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w13, cs=w17; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  casadi_clear(w24, 18);
  casadi_clear(w01, 18);
  casadi_clear(w17, 36);
  for (rr=w18, cs=w13+0; cs!=w13+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w18, cr=wr00, cs=w18; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=w18;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w18, cs=w13+12; cs!=w13+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w18, cr=wr00, cs=w18; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=w18;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w20;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w18, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w18, cr=wr00, cs=w18; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=w18;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w25;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w21;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w20; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w25; i<12; ++i) *rr++ = *cs++;
  wr03 = casadi_c3;
  casadi_mtimes_dense(w21, 12, 3, wr03, 3, w17, 0);
  for (i=0, rr=w17, cs=w17; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w17, cr=w13, cs=w17; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w06, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w22, 18);
  for (rr=w23, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w23, 1, w22, 0);
  for (i=0, rr=w06, cs=w22; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w06, 1, w01, 0);
  for (i=0, rr=w01, cs=w01; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w01, casadi_s26, w24, casadi_s26, w, 0);
  for (i=0, rr=w24, cs=w23; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w23, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w24, cs=w01; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w17;
  for (i=0, cs=w23; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w21, cs=w17; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w13, cs=w21; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w23, 18);
  casadi_clear(w24, 18);
  casadi_clear(w21, 36);
  for (rr=w19, cs=w13+0; cs!=w13+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w20;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w13+12; cs!=w13+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w25;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w18;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w17;
  for (i=0, cs=w20; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w25; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w18; i<12; ++i) *rr++ = *cs++;
  wr03 = casadi_c3;
  casadi_mtimes_dense(w17, 12, 3, wr03, 3, w21, 0);
  for (i=0, rr=w21, cs=w21; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w21, cr=w13, cs=w21; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w01, cs=w21+0; cs!=w21+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w06, 18);
  for (rr=w22, cs=w21+0; cs!=w21+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w22, 1, w06, 0);
  for (i=0, rr=w01, cs=w06; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w01, 1, w24, 0);
  for (i=0, rr=w24, cs=w24; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w24, casadi_s26, w23, casadi_s26, w, 0);
  for (i=0, rr=w23, cs=w22; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w22, cs=w23; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w23, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w21;
  for (i=0, cs=w22; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w23; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w17, cs=w21; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w13, cs=w17; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w22, 18);
  casadi_clear(w23, 18);
  casadi_clear(w17, 36);
  for (rr=w20, cs=w13+0; cs!=w13+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w20, cr=wr00, cs=w20; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=w20;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w25;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w20, cs=w13+12; cs!=w13+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w20, cr=wr00, cs=w20; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=w20;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w18;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w20, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w20, cr=wr00, cs=w20; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=w20;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w21;
  for (i=0, cs=w25; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w18; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  wr03 = casadi_c3;
  casadi_mtimes_dense(w21, 12, 3, wr03, 3, w17, 0);
  for (i=0, rr=w17, cs=w17; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w17, cr=w13, cs=w17; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w24, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w01, 18);
  for (rr=w06, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w06, 1, w01, 0);
  for (i=0, rr=w24, cs=w01; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w24, 1, w23, 0);
  for (i=0, rr=w23, cs=w23; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w23, casadi_s26, w22, casadi_s26, w, 0);
  for (i=0, rr=w22, cs=w06; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w06, cs=w22; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w22, cs=w23; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w17;
  for (i=0, cs=w06; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w22; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w21, cs=w17; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w13, cs=w21; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w06, 18);
  casadi_clear(w22, 18);
  casadi_clear(w21, 36);
  for (rr=w25, cs=w13+0; cs!=w13+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w25, cr=wr00, cs=w25; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=w25;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w18;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w25, cs=w13+12; cs!=w13+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w25, cr=wr00, cs=w25; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=w25;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w25, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w25, cr=wr00, cs=w25; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=w25;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w20;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w17;
  for (i=0, cs=w18; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w20; i<12; ++i) *rr++ = *cs++;
  wr03 = casadi_c3;
  casadi_mtimes_dense(w17, 12, 3, wr03, 3, w21, 0);
  for (i=0, rr=w21, cs=w21; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w21, cr=w13, cs=w21; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w23, cs=w21+0; cs!=w21+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w24, 18);
  for (rr=w01, cs=w21+0; cs!=w21+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w01, 1, w24, 0);
  for (i=0, rr=w23, cs=w24; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w23, 1, w22, 0);
  for (i=0, rr=w22, cs=w22; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w22, casadi_s26, w06, casadi_s26, w, 0);
  for (i=0, rr=w06, cs=w01; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w01, cs=w06; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w06, cs=w22; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w21;
  for (i=0, cs=w01; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w06; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w17, cs=w21; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w13, cs=w17; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w01, 18);
  casadi_clear(w06, 18);
  casadi_clear(w17, 36);
  for (rr=w18, cs=w13+0; cs!=w13+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w18, cr=wr00, cs=w18; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=w18;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w18, cs=w13+12; cs!=w13+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w18, cr=wr00, cs=w18; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=w18;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w20;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w18, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w18, cr=wr00, cs=w18; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=w18;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w25;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w21;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w20; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w25; i<12; ++i) *rr++ = *cs++;
  wr03 = casadi_c3;
  casadi_mtimes_dense(w21, 12, 3, wr03, 3, w17, 0);
  for (i=0, rr=w17, cs=w17; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w17, cr=w13, cs=w17; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w22, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w23, 18);
  for (rr=w24, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w24, 1, w23, 0);
  for (i=0, rr=w22, cs=w23; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w22, 1, w06, 0);
  for (i=0, rr=w06, cs=w06; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w06, casadi_s26, w01, casadi_s26, w, 0);
  for (i=0, rr=w01, cs=w24; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w24, cs=w01; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w01, cs=w06; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w17;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w01; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w21, cs=w17; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w13, cs=w21; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w24, 18);
  casadi_clear(w01, 18);
  casadi_clear(w21, 36);
  for (rr=w19, cs=w13+0; cs!=w13+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w20;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w13+12; cs!=w13+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w25;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=w19;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w18;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w17;
  for (i=0, cs=w20; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w25; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w18; i<12; ++i) *rr++ = *cs++;
  wr03 = casadi_c3;
  casadi_mtimes_dense(w17, 12, 3, wr03, 3, w21, 0);
  for (i=0, rr=w21, cs=w21; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w21, cr=w13, cs=w21; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w06, cs=w21+0; cs!=w21+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w22, 18);
  for (rr=w23, cs=w21+0; cs!=w21+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w23, 1, w22, 0);
  for (i=0, rr=w06, cs=w22; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w06, 1, w01, 0);
  for (i=0, rr=w01, cs=w01; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w01, casadi_s26, w24, casadi_s26, w, 0);
  for (i=0, rr=w24, cs=w23; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w23, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w24, cs=w01; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w21;
  for (i=0, cs=w23; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w17, cs=w21; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w13, cs=w17; i<36; ++i) (*rr++) += (*cs++);
  casadi_clear(w23, 18);
  casadi_clear(w24, 18);
  casadi_clear(w17, 36);
  for (rr=w20, cs=w13+0; cs!=w13+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w20, cr=wr00, cs=w20; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  arg1[0]=w20;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w25;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w20, cs=w13+12; cs!=w13+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w20, cr=wr00, cs=w20; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=w20;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w18;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w20, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w20, cr=wr00, cs=w20; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  for (rr=w09, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=w20;
  arg1[1]=w09;
  arg1[2]=wr10;
  arg1[3]=w11;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w21;
  for (i=0, cs=w25; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w18; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  wr03 = casadi_c3;
  casadi_mtimes_dense(w21, 12, 3, wr03, 3, w17, 0);
  for (i=0, rr=w17, cs=w17; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w17, cr=w13, cs=w17; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w01, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_clear(w06, 18);
  for (rr=w22, cs=w17+0; cs!=w17+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_mtimes_dense(w08, 18, 18, w22, 1, w06, 0);
  for (i=0, rr=w01, cs=w06; i<18; ++i) (*rr++) += (*cs++);
  casadi_mtimes_dense(w07, 18, 18, w01, 1, w24, 0);
  for (i=0, rr=w24, cs=w24; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s27, w24, casadi_s26, w23, casadi_s26, w, 0);
  for (i=0, rr=w23, cs=w22; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w22, cs=w23; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w23, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w17;
  for (i=0, cs=w22; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w23; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w21, cs=w17; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w13, cs=w21; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w25, cs=w13+24; cs!=w13+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w00, cr=wr00, cs=w25; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  casadi_copy(w00, 12, res[0]);
  w02 = casadi_norm_inf(36, w21);
  if (res[1]) res[1][0] = w02;
  return 0;
}

CASADI_SYMBOL_EXPORT int radau_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f11(arg, res, iw, w, mem);
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
  if (sz_arg) *sz_arg = 14;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 13;
  if (sz_w) *sz_w = 1946;
  return 0;
}

CASADI_SYMBOL_EXPORT int radau_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 14*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 13*sizeof(casadi_int);
  if (sz_w) *sz_w = 1946*sizeof(casadi_real);
  return 0;
}


