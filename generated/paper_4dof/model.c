/* GENERATED FILE: DO NOT EDIT.
 * Regenerate: `jointplay derive robot.toml --out <this folder>`, or for the models
 * checked in under generated/: `pytest tests/test_generated.py --update-generated`.
 * model: paper_4dof
 * generator: jointplay.derive 0.1.0+6235263689d5, casadi 3.8.2, sympy 1.14.0
 * formulation: closed
 * input hash: b7ef2896db5fe14ac39070c635dc9aef476bf3b6c97d931d67a3e5f2442f0012
 * Every input and output slot is described, with names and units, in layout.json.
 * Functions (inputs -> outputs; column vectors, dense, float64):
 *   mass_matrix(q[6], p[39]) -> M[6x6]
 *   forcing(x[12], tau[2], p[39], v_imp[2]) -> f[6x1]
 *   forward_dynamics(x[12], tau[2], p[39], v_imp[2]) -> xdot[12x1]
 *   jac_forward_dynamics: d forward_dynamics / d each input, CasADi's calling convention
 *   jac_state(x[12], tau[2], p[39], v_imp[2]) -> jac_xdot_x[12x12]
 *   contact(x[12], p[39], v_imp[2]) -> delta[2x1], delta_dot[2x1], v_t[2x1], f_n[2x1], f_t[2x1], f_x[2x1], f_y[2x1], dissipation[2x1]
 *   normal_force(x[12], p[39], v_imp[2]) -> f_n[2x1]
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
static const casadi_int casadi_s11[3] = {1, 1, 1};
static const casadi_int casadi_s12[3] = {2, 3, 1};
static const casadi_int casadi_s13[15] = 
  {6, 6, 0, 1, 2, 3, 4, 5,
  6, 0, 1, 2, 3, 4, 5};
static const casadi_int casadi_s14[18] = 
  {0, 1, 2, 3, 4, 5, 6, 7,
  8, 9, 10, 11, 12, 13, 14, 15,
  16, 17};
static const casadi_int casadi_s15[345] = 
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
static const casadi_int casadi_s16[192] = 
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
static const casadi_int casadi_s17[192] = 
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
static const casadi_int casadi_s18[22] = 
  {18, 1, 0, 18, 0, 1, 2, 3,
  4, 5, 6, 7, 8, 9, 10, 11,
  12, 13, 14, 15, 16, 17};
static const casadi_int casadi_s19[75] = 
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
  casadi_real **res1=res+1, *rr, *w1=w+56, *w2=w+62, *w4=w+64, *w6=w+66;
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
  if (sz_w) *sz_w = 102;
  return 0;
}

CASADI_SYMBOL_EXPORT int forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 102*sizeof(casadi_real);
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
  casadi_real a096, a097, a098, a099, a100, a101, a102;
  a000=arg[1]? arg[1][0] : 0;
  a001=arg[3]? arg[3][9] : 0;
  a002=arg[3]? arg[3][4] : 0;
  a003=arg[3]? arg[3][19] : 0;
  a004=arg[0]? arg[0][0] : 0;
  a005=(a003+a004);
  a006=sin(a005);
  a007=(a002*a006);
  a008=arg[3]? arg[3][11] : 0;
  a009=arg[0]? arg[0][1] : 0;
  a010=(a005+a009);
  a011=sin(a010);
  a012=(a008*a011);
  a013=(a007+a012);
  a014=(2.*a013);
  a005=cos(a005);
  a015=(a002*a005);
  a010=cos(a010);
  a016=(a008*a010);
  a017=(a015+a016);
  a018=(a014*a017);
  a019=(2.*a017);
  a020=(a019*a013);
  a018=(a018-a020);
  a018=(a001*a018);
  a020=arg[3]? arg[3][13] : 0;
  a021=arg[3]? arg[3][8] : 0;
  a022=(a021*a011);
  a007=(a007+a022);
  a023=arg[3]? arg[3][15] : 0;
  a024=arg[3]? arg[3][32] : 0;
  a003=(a003+a024);
  a003=(a003+a004);
  a003=(a003+a009);
  a009=sin(a003);
  a004=(a023*a009);
  a024=(a007+a004);
  a025=(2.*a024);
  a026=(a021*a010);
  a015=(a015+a026);
  a003=cos(a003);
  a027=(a023*a003);
  a028=(a015+a027);
  a029=(a025*a028);
  a030=(2.*a028);
  a031=(a030*a024);
  a029=(a029-a031);
  a029=(a020*a029);
  a018=(a018+a029);
  a029=arg[3]? arg[3][16] : 0;
  a031=arg[3]? arg[3][12] : 0;
  a032=(a031*a009);
  a007=(a007+a032);
  a033=(2.*a007);
  a034=(a031*a003);
  a015=(a015+a034);
  a035=(a033*a015);
  a036=(2.*a015);
  a037=(a036*a007);
  a035=(a035-a037);
  a035=(a029*a035);
  a018=(a018+a035);
  a018=(a000*a018);
  a035=arg[1]? arg[1][1] : 0;
  a037=(a008*a017);
  a038=(a011*a037);
  a039=(a008*a013);
  a040=(a039*a010);
  a038=(a038+a040);
  a039=(a010*a039);
  a037=(a037*a011);
  a039=(a039+a037);
  a038=(a038-a039);
  a038=(a001*a038);
  a027=(a026+a027);
  a039=(a024*a027);
  a004=(a022+a004);
  a041=(a004*a028);
  a041=(a039+a041);
  a042=(a028*a004);
  a043=(a027*a024);
  a043=(a042+a043);
  a041=(a041-a043);
  a041=(a020*a041);
  a038=(a038+a041);
  a026=(a026+a034);
  a034=(a007*a026);
  a022=(a022+a032);
  a032=(a022*a015);
  a032=(a034+a032);
  a041=(a015*a022);
  a043=(a026*a007);
  a043=(a041+a043);
  a032=(a032-a043);
  a032=(a029*a032);
  a038=(a038+a032);
  a032=(a035*a038);
  a018=(a018+a032);
  a032=arg[1]? arg[1][2] : 0;
  a043=(a001*a017);
  a044=(a020*a028);
  a045=(a043+a044);
  a046=(a029*a015);
  a045=(a045+a046);
  a047=arg[3]? arg[3][7] : 0;
  a048=arg[3]? arg[3][5] : 0;
  a049=(a047*a048);
  a050=(a049*a005);
  a050=(a045+a050);
  a051=(a032*a050);
  a018=(a018-a051);
  a051=arg[1]? arg[1][3] : 0;
  a052=(a001*a013);
  a053=(a020*a024);
  a054=(a052+a053);
  a055=(a029*a007);
  a054=(a054+a055);
  a056=(a049*a006);
  a056=(a054+a056);
  a057=(a051*a056);
  a018=(a018-a057);
  a057=arg[1]? arg[1][4] : 0;
  a058=(a057*a045);
  a018=(a018-a058);
  a058=arg[1]? arg[1][5] : 0;
  a059=(a058*a054);
  a018=(a018-a059);
  a059=arg[0]? arg[0][6] : 0;
  a060=casadi_sq(a059);
  a061=(a002*a060);
  a062=(a061*a005);
  a063=arg[0]? arg[0][7] : 0;
  a063=(a059+a063);
  a064=casadi_sq(a063);
  a065=(a008*a064);
  a066=(a065*a010);
  a067=(a062+a066);
  a068=(a043*a067);
  a061=(a061*a006);
  a065=(a065*a011);
  a069=(a061+a065);
  a070=(a069*a052);
  a068=(a068-a070);
  a070=arg[3]? arg[3][17] : 0;
  a071=(a070*a001);
  a017=(a071*a017);
  a072=(a070*a020);
  a028=(a072*a028);
  a017=(a017+a028);
  a028=(a070*a029);
  a015=(a028*a015);
  a017=(a017+a015);
  a015=arg[3]? arg[3][18] : 0;
  a073=(a015*a001);
  a013=(a073*a013);
  a017=(a017+a013);
  a013=(a015*a020);
  a024=(a013*a024);
  a017=(a017+a024);
  a024=(a015*a029);
  a007=(a024*a007);
  a017=(a017+a007);
  a068=(a068-a017);
  a017=(a067*a043);
  a007=(a052*a069);
  a017=(a017-a007);
  a068=(a068-a017);
  a017=(a021*a064);
  a007=(a017*a010);
  a062=(a062+a007);
  a074=(a023*a064);
  a075=(a074*a003);
  a076=(a062+a075);
  a077=(a044*a076);
  a017=(a017*a011);
  a061=(a061+a017);
  a074=(a074*a009);
  a078=(a061+a074);
  a079=(a078*a053);
  a077=(a077-a079);
  a068=(a068+a077);
  a077=(a076*a044);
  a079=(a053*a078);
  a077=(a077-a079);
  a068=(a068-a077);
  a064=(a031*a064);
  a077=(a064*a003);
  a062=(a062+a077);
  a079=(a046*a062);
  a064=(a064*a009);
  a061=(a061+a064);
  a080=(a061*a055);
  a079=(a079-a080);
  a068=(a068+a079);
  a079=(a062*a046);
  a080=(a055*a061);
  a079=(a079-a080);
  a068=(a068-a079);
  a079=(a047*a015);
  a079=(a079*a048);
  a079=(a079*a006);
  a068=(a068-a079);
  a047=(a047*a070);
  a047=(a047*a048);
  a047=(a047*a005);
  a068=(a068-a047);
  a018=(a018-a068);
  if (res[0]!=0) res[0][0]=a018;
  a038=(a000*a038);
  a018=(2.*a004);
  a018=(a018*a027);
  a068=(2.*a027);
  a068=(a068*a004);
  a018=(a018-a068);
  a018=(a020*a018);
  a068=(2.*a022);
  a068=(a068*a026);
  a047=(2.*a026);
  a047=(a047*a022);
  a068=(a068-a047);
  a068=(a029*a068);
  a018=(a018+a068);
  a018=(a035*a018);
  a038=(a038+a018);
  a068=(a020*a027);
  a047=(a029*a026);
  a048=(a068+a047);
  a079=(a008*a001);
  a080=(a079*a010);
  a048=(a048+a080);
  a080=(a032*a048);
  a038=(a038-a080);
  a081=(a020*a004);
  a082=(a029*a022);
  a083=(a081+a082);
  a084=(a079*a011);
  a083=(a083+a084);
  a084=(a051*a083);
  a038=(a038-a084);
  a085=(a057*a048);
  a038=(a038-a085);
  a086=(a058*a083);
  a038=(a038-a086);
  a087=(a068*a076);
  a088=(a078*a081);
  a087=(a087-a088);
  a072=(a072*a027);
  a028=(a028*a026);
  a089=(a072+a028);
  a013=(a013*a004);
  a089=(a089+a013);
  a024=(a024*a022);
  a089=(a089+a024);
  a087=(a087-a089);
  a090=(a076*a068);
  a091=(a081*a078);
  a091=(a090-a091);
  a087=(a087-a091);
  a091=(a047*a062);
  a092=(a061*a082);
  a091=(a091-a092);
  a087=(a087+a091);
  a091=(a062*a047);
  a093=(a082*a061);
  a093=(a091-a093);
  a087=(a087-a093);
  a015=(a008*a015);
  a015=(a015*a001);
  a015=(a015*a011);
  a087=(a087-a015);
  a093=(a079*a067);
  a094=(a093*a010);
  a095=(a079*a069);
  a096=(a011*a095);
  a096=(a094-a096);
  a087=(a087-a096);
  a070=(a008*a070);
  a070=(a070*a001);
  a070=(a070*a010);
  a087=(a087-a070);
  a093=(a010*a093);
  a095=(a095*a011);
  a093=(a093-a095);
  a087=(a087+a093);
  a038=(a038-a087);
  if (res[0]!=0) res[0][1]=a038;
  a038=(a001*a069);
  a078=(a020*a078);
  a038=(a038+a078);
  a061=(a029*a061);
  a038=(a038+a061);
  a060=(a049*a060);
  a061=(a060*a006);
  a061=(a038+a061);
  a050=(a000*a050);
  a048=(a035*a048);
  a050=(a050+a048);
  a061=(a061-a050);
  if (res[0]!=0) res[0][2]=a061;
  a056=(a000*a056);
  a083=(a035*a083);
  a056=(a056+a083);
  a061=(a001*a067);
  a076=(a020*a076);
  a061=(a061+a076);
  a062=(a029*a062);
  a061=(a061+a062);
  a060=(a060*a005);
  a060=(a061+a060);
  a056=(a056+a060);
  a056=(-a056);
  if (res[0]!=0) res[0][3]=a056;
  a045=(a000*a045);
  a045=(a045+a048);
  a038=(a038-a045);
  if (res[0]!=0) res[0][4]=a038;
  a054=(a000*a054);
  a054=(a054+a083);
  a054=(a054+a061);
  a054=(-a054);
  if (res[0]!=0) res[0][5]=a054;
  a014=(a014*a016);
  a019=(a019*a012);
  a014=(a014-a019);
  a014=(a001*a014);
  a025=(a025*a027);
  a030=(a030*a004);
  a025=(a025-a030);
  a025=(a020*a025);
  a014=(a014+a025);
  a033=(a033*a026);
  a036=(a036*a022);
  a033=(a033-a036);
  a033=(a029*a033);
  a014=(a014+a033);
  a014=(a000*a014);
  a033=(a008*a016);
  a033=(a011*a033);
  a033=(a033+a040);
  a040=(a008*a012);
  a040=(a010*a040);
  a040=(a040+a037);
  a033=(a033-a040);
  a033=(a001*a033);
  a040=(a004*a027);
  a039=(a039+a040);
  a027=(a027*a004);
  a042=(a042+a027);
  a039=(a039-a042);
  a039=(a020*a039);
  a033=(a033+a039);
  a039=(a022*a026);
  a034=(a034+a039);
  a026=(a026*a022);
  a041=(a041+a026);
  a034=(a034-a041);
  a034=(a029*a034);
  a033=(a033+a034);
  a035=(a035*a033);
  a014=(a014+a035);
  a035=(a001*a016);
  a034=(a035+a068);
  a034=(a034+a047);
  a032=(a032*a034);
  a014=(a014-a032);
  a032=(a001*a012);
  a041=(a032+a081);
  a041=(a041+a082);
  a051=(a051*a041);
  a014=(a014-a051);
  a057=(a057*a034);
  a014=(a014-a057);
  a058=(a058*a041);
  a014=(a014-a058);
  a058=(a043*a066);
  a069=(a069*a032);
  a058=(a058-a069);
  a071=(a071*a016);
  a071=(a071+a072);
  a071=(a071+a028);
  a073=(a073*a012);
  a071=(a071+a073);
  a071=(a071+a013);
  a071=(a071+a024);
  a058=(a058-a071);
  a067=(a067*a035);
  a035=(a052*a065);
  a067=(a067-a035);
  a058=(a058-a067);
  a075=(a007+a075);
  a067=(a044*a075);
  a067=(a067-a088);
  a058=(a058+a067);
  a074=(a017+a074);
  a067=(a053*a074);
  a067=(a090-a067);
  a058=(a058-a067);
  a007=(a007+a077);
  a077=(a046*a007);
  a077=(a077-a092);
  a058=(a058+a077);
  a017=(a017+a064);
  a064=(a055*a017);
  a064=(a091-a064);
  a058=(a058-a064);
  a014=(a014-a058);
  if (res[0]!=0) res[0][6]=a014;
  a033=(a000*a033);
  a033=(a033+a018);
  a033=(a033-a080);
  a033=(a033-a084);
  a033=(a033-a085);
  a033=(a033-a086);
  a086=(a068*a075);
  a086=(a086-a088);
  a086=(a086-a089);
  a089=(a081*a074);
  a090=(a090-a089);
  a086=(a086-a090);
  a090=(a047*a007);
  a090=(a090-a092);
  a086=(a086+a090);
  a090=(a082*a017);
  a091=(a091-a090);
  a086=(a086-a091);
  a086=(a086-a015);
  a015=(a079*a065);
  a015=(a011*a015);
  a094=(a094-a015);
  a086=(a086-a094);
  a086=(a086-a070);
  a070=(a079*a066);
  a070=(a010*a070);
  a070=(a070-a095);
  a086=(a086+a070);
  a033=(a033-a086);
  if (res[0]!=0) res[0][7]=a033;
  a065=(a001*a065);
  a074=(a020*a074);
  a065=(a065+a074);
  a017=(a029*a017);
  a065=(a065+a017);
  a034=(a000*a034);
  a034=(a034+a048);
  a065=(a065-a034);
  if (res[0]!=0) res[0][8]=a065;
  a000=(a000*a041);
  a000=(a000+a083);
  a066=(a001*a066);
  a075=(a020*a075);
  a066=(a066+a075);
  a007=(a029*a007);
  a066=(a066+a007);
  a000=(a000+a066);
  a000=(-a000);
  if (res[0]!=0) res[0][9]=a000;
  if (res[0]!=0) res[0][10]=a065;
  if (res[0]!=0) res[0][11]=a000;
  a000=arg[3]? arg[3][21] : 0;
  a065=1.;
  a066=0.;
  a007=(a000*a059);
  a075=-9.9999999999999995e-07;
  a083=(a075*a000);
  a041=9.9999999999999995e-07;
  a034=arg[3]? arg[3][20] : 0;
  a048=(a041*a034);
  a083=(a083+a048);
  a083=casadi_sq(a083);
  a048=arg[0]? arg[0][2] : 0;
  a017=casadi_sq(a048);
  a074=arg[0]? arg[0][3] : 0;
  a033=casadi_sq(a074);
  a017=(a017+a033);
  a033=casadi_fmax(a083,a017);
  a086=-5.0000000000000000e-01;
  a070=pow(a033,a086);
  a095=(a070*a048);
  a094=arg[0]? arg[0][9] : 0;
  a015=(a095*a094);
  a007=(a007+a015);
  a015=(a070*a074);
  a091=arg[0]? arg[0][8] : 0;
  a090=(a015*a091);
  a007=(a007-a090);
  a090=casadi_fabs(a007);
  a092=arg[3]? arg[3][37] : 0;
  a089=(a090-a092);
  a088=arg[3]? arg[3][38] : 0;
  a085=(a088-a092);
  a089=(a089/a085);
  a084=casadi_fmax(a066,a089);
  a080=casadi_fmin(a065,a084);
  a018=sqrt(a033);
  a014=(a000+a018);
  a014=(a014-a034);
  a058=(a066<a014);
  a064=1.3333333333333333e+00;
  a077=(a034*a000);
  a034=(a034-a000);
  a077=(a077/a034);
  a077=sqrt(a077);
  a077=(a064*a077);
  a034=arg[3]? arg[3][23] : 0;
  a034=casadi_sq(a034);
  a034=(a065-a034);
  a067=arg[3]? arg[3][22] : 0;
  a034=(a034/a067);
  a067=arg[3]? arg[3][25] : 0;
  a067=casadi_sq(a067);
  a067=(a065-a067);
  a035=arg[3]? arg[3][24] : 0;
  a067=(a067/a035);
  a034=(a034+a067);
  a077=(a077/a034);
  a034=7.5000000000000000e-01;
  a067=-7.5000000000000000e-01;
  a035=arg[3]? arg[3][34] : 0;
  a035=casadi_sq(a035);
  a067=(a067*a035);
  a034=(a034+a067);
  a067=arg[4]? arg[4][0] : 0;
  a035=arg[3]? arg[3][35] : 0;
  a067=casadi_fmax(a067,a035);
  a067=(a034/a067);
  a071=(a095*a091);
  a024=(a015*a094);
  a071=(a071+a024);
  a071=(a067*a071);
  a071=(a065+a071);
  a071=(a077*a071);
  a024=1.0000000000000000e-300;
  a013=casadi_fmax(a024,a014);
  a073=arg[3]? arg[3][33] : 0;
  a012=pow(a013,a073);
  a028=(a071*a012);
  a028=(a058?a028:0);
  a072=casadi_fmax(a066,a028);
  a016=arg[3]? arg[3][36] : 0;
  a069=1.0000000000000000e-03;
  a069=(a069*a088);
  a069=casadi_fmax(a092,a069);
  a088=casadi_fmax(a069,a090);
  a032=(a016/a088);
  a057=-1.5000000000000000e+00;
  a033=pow(a033,a057);
  a033=(a086*a033);
  a051=(a083<=a017);
  a017=(a017<=a083);
  a017=(a017+a051);
  a051=(a051/a017);
  a017=(2.*a048);
  a017=(a051*a017);
  a083=(a033*a017);
  a026=(a048*a083);
  a026=(a026+a070);
  a022=(a094*a026);
  a039=(a074*a083);
  a042=(a091*a039);
  a022=(a022-a042);
  a042=(a032*a022);
  a027=(a032/a088);
  a004=(a069<=a090);
  a090=(a090<=a069);
  a090=(a090+a004);
  a004=(a004/a090);
  a090=casadi_sign(a007);
  a040=(a090*a022);
  a037=(a004*a040);
  a036=(a027*a037);
  a036=(a007*a036);
  a042=(a042-a036);
  a042=(a072*a042);
  a036=(a032*a007);
  a025=(a066<=a028);
  a028=(a028<=a066);
  a028=(a028+a025);
  a025=(a025/a028);
  a026=(a091*a026);
  a039=(a094*a039);
  a026=(a026+a039);
  a026=(a067*a026);
  a026=(a077*a026);
  a026=(a012*a026);
  a039=(a073-a065);
  a013=pow(a013,a039);
  a013=(a073*a013);
  a028=(a024<=a014);
  a014=(a014<=a024);
  a014=(a014+a028);
  a028=(a028/a014);
  a018=(2.*a018);
  a017=(a017/a018);
  a017=(a028*a017);
  a017=(a013*a017);
  a017=(a071*a017);
  a026=(a026+a017);
  a026=(a025*a026);
  a017=(a036*a026);
  a017=(a058?a017:0);
  a042=(a042+a017);
  a042=(a080*a042);
  a017=(a036*a072);
  a014=(a084<=a065);
  a084=(a065<=a084);
  a084=(a084+a014);
  a014=(a014/a084);
  a084=(a066<=a089);
  a089=(a089<=a066);
  a089=(a089+a084);
  a084=(a084/a089);
  a040=(a040/a085);
  a040=(a084*a040);
  a040=(a014*a040);
  a089=(a017*a040);
  a042=(a042+a089);
  a042=(a000*a042);
  if (res[0]!=0) res[0][12]=a042;
  a042=(a016*a083);
  a042=(a042/a088);
  a089=(a016*a070);
  a089=(a089/a088);
  a030=(a089/a088);
  a037=(a030*a037);
  a042=(a042-a037);
  a042=(a007*a042);
  a022=(a089*a022);
  a042=(a042+a022);
  a042=(a072*a042);
  a022=(a089*a007);
  a037=(a022*a026);
  a037=(a058?a037:0);
  a042=(a042+a037);
  a042=(a080*a042);
  a037=(a022*a072);
  a040=(a037*a040);
  a042=(a042+a040);
  a040=(a074*a042);
  a083=(a072*a083);
  a026=(a070*a026);
  a026=(a058?a026:0);
  a083=(a083+a026);
  a026=(a048*a083);
  a019=(a070*a072);
  a026=(a026+a019);
  a040=(a040-a026);
  a040=(-a040);
  if (res[0]!=0) res[0][13]=a040;
  a083=(a074*a083);
  a042=(a048*a042);
  a040=(a037*a080);
  a042=(a042+a040);
  a083=(a083+a042);
  if (res[0]!=0) res[0][14]=a083;
  a083=(2.*a074);
  a051=(a051*a083);
  a033=(a033*a051);
  a083=(a048*a033);
  a042=(a094*a083);
  a026=(a074*a033);
  a026=(a026+a070);
  a054=(a091*a026);
  a042=(a042-a054);
  a054=(a032*a042);
  a061=(a090*a042);
  a038=(a004*a061);
  a045=(a027*a038);
  a045=(a007*a045);
  a054=(a054-a045);
  a054=(a072*a054);
  a091=(a091*a083);
  a094=(a094*a026);
  a091=(a091+a094);
  a091=(a067*a091);
  a091=(a077*a091);
  a091=(a012*a091);
  a051=(a051/a018);
  a028=(a028*a051);
  a013=(a013*a028);
  a071=(a071*a013);
  a091=(a091+a071);
  a091=(a025*a091);
  a071=(a036*a091);
  a071=(a058?a071:0);
  a054=(a054+a071);
  a054=(a080*a054);
  a061=(a061/a085);
  a061=(a084*a061);
  a061=(a014*a061);
  a071=(a017*a061);
  a054=(a054+a071);
  a054=(a000*a054);
  if (res[0]!=0) res[0][15]=a054;
  a054=(a016*a033);
  a054=(a054/a088);
  a038=(a030*a038);
  a054=(a054-a038);
  a054=(a007*a054);
  a042=(a089*a042);
  a054=(a054+a042);
  a054=(a072*a054);
  a042=(a022*a091);
  a042=(a058?a042:0);
  a054=(a054+a042);
  a054=(a080*a054);
  a061=(a037*a061);
  a054=(a054+a061);
  a061=(a074*a054);
  a061=(a061+a040);
  a033=(a072*a033);
  a091=(a070*a091);
  a091=(a058?a091:0);
  a033=(a033+a091);
  a091=(a048*a033);
  a061=(a061-a091);
  a061=(-a061);
  if (res[0]!=0) res[0][16]=a061;
  a033=(a074*a033);
  a033=(a033+a019);
  a054=(a048*a054);
  a033=(a033+a054);
  if (res[0]!=0) res[0][17]=a033;
  a033=arg[3]? arg[3][26] : 0;
  a054=(a033*a059);
  a019=arg[3]? arg[3][27] : 0;
  a061=(a019*a063);
  a091=(a054-a061);
  a075=(a075*a019);
  a041=(a041*a033);
  a075=(a075+a041);
  a075=casadi_sq(a075);
  a041=arg[0]? arg[0][4] : 0;
  a040=casadi_sq(a041);
  a042=arg[0]? arg[0][5] : 0;
  a038=casadi_sq(a042);
  a040=(a040+a038);
  a038=casadi_fmax(a075,a040);
  a088=pow(a038,a086);
  a071=(a088*a042);
  a013=arg[0]? arg[0][10] : 0;
  a028=(a071*a013);
  a091=(a091+a028);
  a051=(a088*a041);
  a018=arg[0]? arg[0][11] : 0;
  a094=(a051*a018);
  a091=(a091-a094);
  a026=casadi_fabs(a091);
  a092=(a026-a092);
  a092=(a092/a085);
  a083=casadi_fmax(a066,a092);
  a045=casadi_fmin(a065,a083);
  a056=sqrt(a038);
  a060=(a019+a056);
  a060=(a060-a033);
  a062=(a066<a060);
  a076=(a033*a019);
  a050=(a033-a019);
  a076=(a076/a050);
  a076=sqrt(a076);
  a064=(a064*a076);
  a076=arg[3]? arg[3][29] : 0;
  a076=casadi_sq(a076);
  a076=(a065-a076);
  a078=arg[3]? arg[3][28] : 0;
  a076=(a076/a078);
  a078=arg[3]? arg[3][31] : 0;
  a078=casadi_sq(a078);
  a078=(a065-a078);
  a087=arg[3]? arg[3][30] : 0;
  a078=(a078/a087);
  a076=(a076+a078);
  a064=(a064/a076);
  a076=arg[4]? arg[4][1] : 0;
  a076=casadi_fmax(a076,a035);
  a034=(a034/a076);
  a076=(a051*a013);
  a035=(a071*a018);
  a076=(a076+a035);
  a076=(a034*a076);
  a076=(a065+a076);
  a076=(a064*a076);
  a035=casadi_fmax(a024,a060);
  a078=pow(a035,a073);
  a087=(a076*a078);
  a087=(a062?a087:0);
  a093=casadi_fmax(a066,a087);
  a096=casadi_fmax(a069,a026);
  a097=(a016/a096);
  a038=pow(a038,a057);
  a086=(a086*a038);
  a038=(a075<=a040);
  a040=(a040<=a075);
  a040=(a040+a038);
  a038=(a038/a040);
  a040=(2.*a041);
  a040=(a038*a040);
  a075=(a086*a040);
  a057=(a041*a075);
  a057=(a057+a088);
  a098=(a018*a057);
  a099=(a042*a075);
  a100=(a013*a099);
  a101=(a098-a100);
  a102=(a097*a101);
  a061=(a061-a054);
  a061=(a061+a094);
  a061=(a061-a028);
  a028=(a097/a096);
  a094=(a069<=a026);
  a026=(a026<=a069);
  a026=(a026+a094);
  a094=(a094/a026);
  a091=casadi_sign(a091);
  a100=(a100-a098);
  a100=(a091*a100);
  a098=(a094*a100);
  a026=(a028*a098);
  a026=(a061*a026);
  a102=(a102-a026);
  a102=(a093*a102);
  a026=(a097*a061);
  a069=(a066<=a087);
  a087=(a087<=a066);
  a087=(a087+a069);
  a069=(a069/a087);
  a057=(a013*a057);
  a099=(a018*a099);
  a057=(a057+a099);
  a057=(a034*a057);
  a057=(a064*a057);
  a057=(a078*a057);
  a035=pow(a035,a039);
  a073=(a073*a035);
  a035=(a024<=a060);
  a060=(a060<=a024);
  a060=(a060+a035);
  a035=(a035/a060);
  a056=(2.*a056);
  a040=(a040/a056);
  a040=(a035*a040);
  a040=(a073*a040);
  a040=(a076*a040);
  a057=(a057+a040);
  a057=(a069*a057);
  a040=(a026*a057);
  a040=(a062?a040:0);
  a102=(a102+a040);
  a102=(a045*a102);
  a040=(a026*a093);
  a060=(a083<=a065);
  a065=(a065<=a083);
  a065=(a065+a060);
  a060=(a060/a065);
  a065=(a066<=a092);
  a092=(a092<=a066);
  a092=(a092+a065);
  a065=(a065/a092);
  a100=(a100/a085);
  a100=(a065*a100);
  a100=(a060*a100);
  a092=(a040*a100);
  a102=(a102+a092);
  a092=(a033*a102);
  a102=(a019*a102);
  a092=(a092-a102);
  a092=(-a092);
  if (res[0]!=0) res[0][18]=a092;
  if (res[0]!=0) res[0][19]=a102;
  a102=(a016*a075);
  a102=(a102/a096);
  a092=(a016*a088);
  a092=(a092/a096);
  a066=(a092/a096);
  a098=(a066*a098);
  a102=(a102-a098);
  a102=(a061*a102);
  a101=(a092*a101);
  a102=(a102+a101);
  a102=(a093*a102);
  a101=(a092*a061);
  a098=(a101*a057);
  a098=(a062?a098:0);
  a102=(a102+a098);
  a102=(a045*a102);
  a098=(a101*a093);
  a100=(a098*a100);
  a102=(a102+a100);
  a100=(a042*a102);
  a075=(a093*a075);
  a057=(a088*a057);
  a057=(a062?a057:0);
  a075=(a075+a057);
  a057=(a041*a075);
  a083=(a088*a093);
  a057=(a057+a083);
  a100=(a100-a057);
  a100=(-a100);
  if (res[0]!=0) res[0][20]=a100;
  a075=(a042*a075);
  a102=(a041*a102);
  a100=(a098*a045);
  a102=(a102+a100);
  a075=(a075+a102);
  if (res[0]!=0) res[0][21]=a075;
  a075=(2.*a042);
  a038=(a038*a075);
  a086=(a086*a038);
  a075=(a041*a086);
  a102=(a018*a075);
  a057=(a042*a086);
  a057=(a057+a088);
  a024=(a013*a057);
  a039=(a102-a024);
  a099=(a097*a039);
  a024=(a024-a102);
  a024=(a091*a024);
  a102=(a094*a024);
  a087=(a028*a102);
  a087=(a061*a087);
  a099=(a099-a087);
  a099=(a093*a099);
  a013=(a013*a075);
  a018=(a018*a057);
  a013=(a013+a018);
  a013=(a034*a013);
  a013=(a064*a013);
  a013=(a078*a013);
  a038=(a038/a056);
  a035=(a035*a038);
  a073=(a073*a035);
  a076=(a076*a073);
  a013=(a013+a076);
  a013=(a069*a013);
  a076=(a026*a013);
  a076=(a062?a076:0);
  a099=(a099+a076);
  a099=(a045*a099);
  a024=(a024/a085);
  a024=(a065*a024);
  a024=(a060*a024);
  a076=(a040*a024);
  a099=(a099+a076);
  a076=(a033*a099);
  a099=(a019*a099);
  a076=(a076-a099);
  a076=(-a076);
  if (res[0]!=0) res[0][22]=a076;
  if (res[0]!=0) res[0][23]=a099;
  a016=(a016*a086);
  a016=(a016/a096);
  a102=(a066*a102);
  a016=(a016-a102);
  a016=(a061*a016);
  a039=(a092*a039);
  a016=(a016+a039);
  a016=(a093*a016);
  a039=(a101*a013);
  a039=(a062?a039:0);
  a016=(a016+a039);
  a016=(a045*a016);
  a024=(a098*a024);
  a016=(a016+a024);
  a024=(a042*a016);
  a024=(a024+a100);
  a086=(a093*a086);
  a013=(a088*a013);
  a013=(a062?a013:0);
  a086=(a086+a013);
  a013=(a041*a086);
  a024=(a024-a013);
  a024=(-a024);
  if (res[0]!=0) res[0][24]=a024;
  a086=(a042*a086);
  a086=(a086+a083);
  a016=(a041*a016);
  a086=(a086+a016);
  if (res[0]!=0) res[0][25]=a086;
  a086=(a019-a033);
  a016=(a097*a086);
  a050=(a091*a050);
  a083=(a094*a050);
  a024=(a028*a083);
  a024=(a061*a024);
  a016=(a016-a024);
  a016=(a093*a016);
  a016=(a045*a016);
  a050=(a050/a085);
  a050=(a065*a050);
  a050=(a060*a050);
  a024=(a040*a050);
  a016=(a016+a024);
  a024=(a033*a016);
  a013=(a032*a000);
  a100=(a090*a000);
  a039=(a004*a100);
  a102=(a027*a039);
  a102=(a007*a102);
  a013=(a013-a102);
  a013=(a072*a013);
  a013=(a080*a013);
  a100=(a100/a085);
  a100=(a084*a100);
  a100=(a014*a100);
  a102=(a017*a100);
  a013=(a013+a102);
  a013=(a000*a013);
  a016=(a019*a016);
  a013=(a013+a016);
  a024=(a024-a013);
  a059=(2.*a059);
  a002=(a002*a059);
  a013=(a006*a002);
  a063=(2.*a063);
  a008=(a008*a063);
  a102=(a011*a008);
  a096=(a013+a102);
  a099=(a043*a096);
  a024=(a024+a099);
  a002=(a005*a002);
  a008=(a010*a008);
  a099=(a002+a008);
  a076=(a052*a099);
  a024=(a024-a076);
  a021=(a021*a063);
  a076=(a011*a021);
  a013=(a013+a076);
  a023=(a023*a063);
  a073=(a009*a023);
  a035=(a013+a073);
  a038=(a044*a035);
  a024=(a024+a038);
  a021=(a010*a021);
  a002=(a002+a021);
  a023=(a003*a023);
  a038=(a002+a023);
  a056=(a053*a038);
  a024=(a024-a056);
  a031=(a031*a063);
  a009=(a009*a031);
  a013=(a013+a009);
  a063=(a046*a013);
  a024=(a024+a063);
  a003=(a003*a031);
  a002=(a002+a003);
  a031=(a055*a002);
  a024=(a024-a031);
  a024=(-a024);
  if (res[0]!=0) res[0][26]=a024;
  a024=(a068*a035);
  a024=(a024-a016);
  a016=(a081*a038);
  a024=(a024-a016);
  a016=(a047*a013);
  a024=(a024+a016);
  a016=(a082*a002);
  a024=(a024-a016);
  a016=(a079*a099);
  a016=(a011*a016);
  a024=(a024-a016);
  a016=(a079*a096);
  a016=(a010*a016);
  a024=(a024+a016);
  a024=(-a024);
  if (res[0]!=0) res[0][27]=a024;
  a024=(a089*a000);
  a039=(a030*a039);
  a039=(a007*a039);
  a024=(a024-a039);
  a024=(a072*a024);
  a024=(a080*a024);
  a100=(a037*a100);
  a024=(a024+a100);
  a100=(a074*a024);
  a099=(a001*a099);
  a100=(a100+a099);
  a038=(a020*a038);
  a100=(a100+a038);
  a002=(a029*a002);
  a100=(a100+a002);
  a049=(a049*a059);
  a005=(a005*a049);
  a100=(a100+a005);
  a100=(-a100);
  if (res[0]!=0) res[0][28]=a100;
  a096=(a001*a096);
  a024=(a048*a024);
  a024=(a096-a024);
  a035=(a020*a035);
  a024=(a024+a035);
  a013=(a029*a013);
  a024=(a024+a013);
  a006=(a006*a049);
  a024=(a024+a006);
  a024=(-a024);
  if (res[0]!=0) res[0][29]=a024;
  a086=(a092*a086);
  a083=(a066*a083);
  a083=(a061*a083);
  a086=(a086-a083);
  a086=(a093*a086);
  a086=(a045*a086);
  a050=(a098*a050);
  a086=(a086+a050);
  a050=(a042*a086);
  a050=(a050+a099);
  a050=(a050+a038);
  a050=(a050+a002);
  a050=(-a050);
  if (res[0]!=0) res[0][30]=a050;
  a086=(a041*a086);
  a096=(a096-a086);
  a096=(a096+a035);
  a096=(a096+a013);
  a096=(-a096);
  if (res[0]!=0) res[0][31]=a096;
  a096=(a091*a019);
  a013=(a094*a096);
  a035=(a028*a013);
  a035=(a061*a035);
  a086=(a097*a019);
  a035=(a035+a086);
  a035=(a093*a035);
  a035=(a045*a035);
  a096=(a096/a085);
  a096=(a065*a096);
  a096=(a060*a096);
  a086=(a040*a096);
  a035=(a035-a086);
  a086=(a033*a035);
  a035=(a019*a035);
  a086=(a086-a035);
  a043=(a043*a102);
  a086=(a086+a043);
  a052=(a052*a008);
  a086=(a086-a052);
  a073=(a076+a073);
  a044=(a044*a073);
  a086=(a086+a044);
  a023=(a021+a023);
  a053=(a053*a023);
  a086=(a086-a053);
  a076=(a076+a009);
  a046=(a046*a076);
  a086=(a086+a046);
  a021=(a021+a003);
  a055=(a055*a021);
  a086=(a086-a055);
  a086=(-a086);
  if (res[0]!=0) res[0][32]=a086;
  a068=(a068*a073);
  a068=(a068-a035);
  a081=(a081*a023);
  a068=(a068-a081);
  a047=(a047*a076);
  a068=(a068+a047);
  a082=(a082*a021);
  a068=(a068-a082);
  a082=(a079*a008);
  a011=(a011*a082);
  a068=(a068-a011);
  a079=(a079*a102);
  a010=(a010*a079);
  a068=(a068+a010);
  a068=(-a068);
  if (res[0]!=0) res[0][33]=a068;
  a008=(a001*a008);
  a023=(a020*a023);
  a068=(a008+a023);
  a021=(a029*a021);
  a068=(a068+a021);
  a068=(-a068);
  if (res[0]!=0) res[0][34]=a068;
  a001=(a001*a102);
  a020=(a020*a073);
  a073=(a001+a020);
  a029=(a029*a076);
  a073=(a073+a029);
  a073=(-a073);
  if (res[0]!=0) res[0][35]=a073;
  a013=(a066*a013);
  a013=(a061*a013);
  a073=(a092*a019);
  a013=(a013+a073);
  a013=(a093*a013);
  a013=(a045*a013);
  a096=(a098*a096);
  a013=(a013-a096);
  a096=(a042*a013);
  a096=(a096+a008);
  a096=(a096+a023);
  a096=(a096+a021);
  a096=(-a096);
  if (res[0]!=0) res[0][36]=a096;
  a013=(a041*a013);
  a001=(a001-a013);
  a001=(a001+a020);
  a001=(a001+a029);
  a001=(-a001);
  if (res[0]!=0) res[0][37]=a001;
  a001=(a090*a015);
  a029=(a004*a001);
  a020=(a027*a029);
  a020=(a007*a020);
  a013=(a032*a015);
  a020=(a020-a013);
  a020=(a072*a020);
  a013=(a067*a095);
  a013=(a077*a013);
  a013=(a012*a013);
  a013=(a025*a013);
  a096=(a036*a013);
  a096=(a058?a096:0);
  a020=(a020+a096);
  a020=(a080*a020);
  a001=(a001/a085);
  a001=(a084*a001);
  a001=(a014*a001);
  a096=(a017*a001);
  a020=(a020-a096);
  a020=(a000*a020);
  if (res[0]!=0) res[0][38]=a020;
  a029=(a030*a029);
  a029=(a007*a029);
  a020=(a089*a015);
  a029=(a029-a020);
  a029=(a072*a029);
  a020=(a022*a013);
  a020=(a058?a020:0);
  a029=(a029+a020);
  a029=(a080*a029);
  a001=(a037*a001);
  a029=(a029-a001);
  a001=(a074*a029);
  a013=(a070*a013);
  a020=(a048*a013);
  a020=(-a020);
  a020=(a058?a020:0);
  a001=(a001+a020);
  a001=(-a001);
  if (res[0]!=0) res[0][39]=a001;
  a013=(a074*a013);
  a013=(a058?a013:0);
  a029=(a048*a029);
  a013=(a013+a029);
  if (res[0]!=0) res[0][40]=a013;
  a032=(a032*a095);
  a090=(a090*a095);
  a004=(a004*a090);
  a027=(a027*a004);
  a027=(a007*a027);
  a032=(a032-a027);
  a032=(a072*a032);
  a067=(a067*a015);
  a077=(a077*a067);
  a012=(a012*a077);
  a025=(a025*a012);
  a036=(a036*a025);
  a036=(a058?a036:0);
  a032=(a032+a036);
  a032=(a080*a032);
  a090=(a090/a085);
  a084=(a084*a090);
  a014=(a014*a084);
  a017=(a017*a014);
  a032=(a032+a017);
  a000=(a000*a032);
  if (res[0]!=0) res[0][41]=a000;
  a089=(a089*a095);
  a030=(a030*a004);
  a007=(a007*a030);
  a089=(a089-a007);
  a072=(a072*a089);
  a022=(a022*a025);
  a022=(a058?a022:0);
  a072=(a072+a022);
  a080=(a080*a072);
  a037=(a037*a014);
  a080=(a080+a037);
  a037=(a074*a080);
  a070=(a070*a025);
  a025=(a048*a070);
  a025=(-a025);
  a025=(a058?a025:0);
  a037=(a037+a025);
  a037=(-a037);
  if (res[0]!=0) res[0][42]=a037;
  a074=(a074*a070);
  a058=(a058?a074:0);
  a048=(a048*a080);
  a058=(a058+a048);
  if (res[0]!=0) res[0][43]=a058;
  a058=(a034*a051);
  a058=(a064*a058);
  a058=(a078*a058);
  a058=(a069*a058);
  a048=(a026*a058);
  a048=(a062?a048:0);
  a080=(a091*a071);
  a074=(a094*a080);
  a070=(a028*a074);
  a070=(a061*a070);
  a037=(a097*a071);
  a070=(a070+a037);
  a070=(a093*a070);
  a048=(a048-a070);
  a048=(a045*a048);
  a080=(a080/a085);
  a080=(a065*a080);
  a080=(a060*a080);
  a070=(a040*a080);
  a048=(a048+a070);
  a070=(a033*a048);
  a048=(a019*a048);
  a070=(a070-a048);
  a070=(-a070);
  if (res[0]!=0) res[0][44]=a070;
  if (res[0]!=0) res[0][45]=a048;
  a048=(a101*a058);
  a048=(a062?a048:0);
  a074=(a066*a074);
  a074=(a061*a074);
  a070=(a092*a071);
  a074=(a074+a070);
  a074=(a093*a074);
  a048=(a048-a074);
  a048=(a045*a048);
  a080=(a098*a080);
  a048=(a048+a080);
  a080=(a042*a048);
  a058=(a088*a058);
  a074=(a041*a058);
  a074=(-a074);
  a074=(a062?a074:0);
  a080=(a080+a074);
  a080=(-a080);
  if (res[0]!=0) res[0][46]=a080;
  a058=(a042*a058);
  a058=(a062?a058:0);
  a048=(a041*a048);
  a058=(a058+a048);
  if (res[0]!=0) res[0][47]=a058;
  a091=(a091*a051);
  a094=(a094*a091);
  a028=(a028*a094);
  a028=(a061*a028);
  a097=(a097*a051);
  a028=(a028+a097);
  a028=(a093*a028);
  a034=(a034*a071);
  a064=(a064*a034);
  a078=(a078*a064);
  a069=(a069*a078);
  a026=(a026*a069);
  a026=(a062?a026:0);
  a028=(a028+a026);
  a028=(a045*a028);
  a091=(a091/a085);
  a065=(a065*a091);
  a060=(a060*a065);
  a040=(a040*a060);
  a028=(a028-a040);
  a033=(a033*a028);
  a019=(a019*a028);
  a033=(a033-a019);
  a033=(-a033);
  if (res[0]!=0) res[0][48]=a033;
  if (res[0]!=0) res[0][49]=a019;
  a066=(a066*a094);
  a061=(a061*a066);
  a092=(a092*a051);
  a061=(a061+a092);
  a093=(a093*a061);
  a101=(a101*a069);
  a101=(a062?a101:0);
  a093=(a093+a101);
  a045=(a045*a093);
  a098=(a098*a060);
  a045=(a045-a098);
  a098=(a042*a045);
  a088=(a088*a069);
  a069=(a041*a088);
  a069=(-a069);
  a069=(a062?a069:0);
  a098=(a098+a069);
  a098=(-a098);
  if (res[0]!=0) res[0][50]=a098;
  a042=(a042*a088);
  a062=(a062?a042:0);
  a041=(a041*a045);
  a062=(a062+a041);
  if (res[0]!=0) res[0][51]=a062;
  return 0;
}

/* jac_state:(x[12],tau[2],p[39],v_imp[2])->(jac_xdot_x[12x12,78nz]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real **res1=res+1, *rr, *w00=w+103, *w01=w+109, *w03=w+115, *w05=w+117, *w07=w+119, *w08=w+155, *w09=w+207, *w10=w+279, *w11=w+351, *w12=w+429;
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
  return casadi_f3(arg, res, iw, w, mem);
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
  if (sz_w) *sz_w = 507;
  return 0;
}

CASADI_SYMBOL_EXPORT int jac_state_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 13*sizeof(casadi_int);
  if (sz_w) *sz_w = 507*sizeof(casadi_real);
  return 0;
}

/* contact:(x[12],p[39],v_imp[2])->(delta[2],delta_dot[2],v_t[2],f_n[2],f_t[2],f_x[2],f_y[2],dissipation[2]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32;
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
  a15=(a13*a14);
  a16=(a02*a07);
  a17=arg[0]? arg[0][9] : 0;
  a18=(a16*a17);
  a15=(a15+a18);
  if (res[1]!=0) res[1][0]=a15;
  a01=pow(a01,a12);
  a12=(a01*a03);
  a18=arg[0]? arg[0][10] : 0;
  a19=(a12*a18);
  a20=(a01*a11);
  a21=arg[0]? arg[0][11] : 0;
  a22=(a20*a21);
  a19=(a19+a22);
  if (res[1]!=0) res[1][1]=a19;
  a22=arg[0]? arg[0][6] : 0;
  a23=(a00*a22);
  a13=(a13*a17);
  a23=(a23+a13);
  a16=(a16*a14);
  a23=(a23-a16);
  if (res[2]!=0) res[2][0]=a23;
  a16=arg[0]? arg[0][7] : 0;
  a16=(a22+a16);
  a16=(a08*a16);
  a22=(a09*a22);
  a14=(a16-a22);
  a12=(a12*a21);
  a14=(a14+a12);
  a20=(a20*a18);
  a14=(a14-a20);
  if (res[2]!=0) res[2][1]=a14;
  a18=0.;
  a21=(a18<a06);
  a13=1.3333333333333333e+00;
  a17=(a04*a00);
  a04=(a04-a00);
  a17=(a17/a04);
  a17=sqrt(a17);
  a04=(a13*a17);
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
  a26=(a26*a15);
  a26=(a00+a26);
  a04=(a04*a26);
  a26=1.0000000000000000e-300;
  a06=casadi_fmax(a26,a06);
  a28=arg[1]? arg[1][33] : 0;
  a06=pow(a06,a28);
  a04=(a04*a06);
  a04=(a21?a04:0);
  a04=casadi_fmax(a18,a04);
  if (res[3]!=0) res[3][0]=a04;
  a29=(a18<a10);
  a30=(a09*a08);
  a09=(a09-a08);
  a30=(a30/a09);
  a30=sqrt(a30);
  a13=(a13*a30);
  a09=arg[1]? arg[1][29] : 0;
  a09=casadi_sq(a09);
  a09=(a00-a09);
  a08=arg[1]? arg[1][28] : 0;
  a09=(a09/a08);
  a08=arg[1]? arg[1][31] : 0;
  a08=casadi_sq(a08);
  a08=(a00-a08);
  a31=arg[1]? arg[1][30] : 0;
  a08=(a08/a31);
  a09=(a09+a08);
  a13=(a13/a09);
  a08=arg[2]? arg[2][1] : 0;
  a08=casadi_fmax(a08,a27);
  a25=(a25/a08);
  a25=(a25*a19);
  a25=(a00+a25);
  a13=(a13*a25);
  a26=casadi_fmax(a26,a10);
  a26=pow(a26,a28);
  a13=(a13*a26);
  a13=(a29?a13:0);
  a13=casadi_fmax(a18,a13);
  if (res[3]!=0) res[3][1]=a13;
  a28=arg[1]? arg[1][36] : 0;
  a10=arg[1]? arg[1][37] : 0;
  a25=1.0000000000000000e-03;
  a08=arg[1]? arg[1][38] : 0;
  a25=(a25*a08);
  a25=casadi_fmax(a10,a25);
  a27=casadi_fabs(a23);
  a31=casadi_fmax(a25,a27);
  a32=(a28/a31);
  a32=(a32*a23);
  a32=(a32*a04);
  a27=(a27-a10);
  a08=(a08-a10);
  a27=(a27/a08);
  a27=casadi_fmax(a18,a27);
  a27=casadi_fmin(a00,a27);
  a32=(a32*a27);
  a32=(-a32);
  if (res[4]!=0) res[4][0]=a32;
  a22=(a22-a16);
  a22=(a22+a20);
  a22=(a22-a12);
  a22=casadi_fabs(a22);
  a25=casadi_fmax(a25,a22);
  a12=(a28/a25);
  a12=(a12*a14);
  a12=(a12*a13);
  a22=(a22-a10);
  a22=(a22/a08);
  a18=casadi_fmax(a18,a22);
  a00=casadi_fmin(a00,a18);
  a12=(a12*a00);
  a12=(-a12);
  if (res[4]!=0) res[4][1]=a12;
  a12=(a28*a02);
  a12=(a12/a31);
  a12=(a12*a23);
  a12=(a12*a04);
  a12=(a12*a27);
  a18=(a12*a07);
  a02=(a02*a04);
  a22=(a02*a05);
  a18=(a18-a22);
  if (res[5]!=0) res[5][0]=a18;
  a18=(a28*a01);
  a18=(a18/a25);
  a18=(a18*a14);
  a18=(a18*a13);
  a18=(a18*a00);
  a22=(a18*a11);
  a01=(a01*a13);
  a08=(a01*a03);
  a22=(a22-a08);
  if (res[5]!=0) res[5][1]=a22;
  a02=(a02*a07);
  a12=(a12*a05);
  a02=(a02+a12);
  a02=(-a02);
  if (res[6]!=0) res[6][0]=a02;
  a01=(a01*a11);
  a18=(a18*a03);
  a01=(a01+a18);
  a01=(-a01);
  if (res[6]!=0) res[6][1]=a01;
  a01=-1.3333333333333333e+00;
  a17=(a01*a17);
  a17=(a17/a24);
  a17=(a17*a06);
  a21=(a21?a17:0);
  a21=(a21+a04);
  a15=(a15*a21);
  a23=casadi_sq(a23);
  a23=(a28*a23);
  a23=(a23/a31);
  a23=(a23*a04);
  a23=(a23*a27);
  a15=(a15+a23);
  if (res[7]!=0) res[7][0]=a15;
  a01=(a01*a30);
  a01=(a01/a09);
  a01=(a01*a26);
  a29=(a29?a01:0);
  a29=(a29+a13);
  a19=(a19*a29);
  a14=casadi_sq(a14);
  a28=(a28*a14);
  a28=(a28/a25);
  a28=(a28*a13);
  a28=(a28*a00);
  a19=(a19+a28);
  if (res[7]!=0) res[7][1]=a19;
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

/* normal_force:(x[12],p[39],v_imp[2])->(f_n[2]) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15;
  a00=0.;
  a01=arg[1]? arg[1][21] : 0;
  a02=-9.9999999999999995e-07;
  a03=(a02*a01);
  a04=9.9999999999999995e-07;
  a05=arg[1]? arg[1][20] : 0;
  a06=(a04*a05);
  a03=(a03+a06);
  a03=casadi_sq(a03);
  a06=arg[0]? arg[0][2] : 0;
  a07=casadi_sq(a06);
  a08=arg[0]? arg[0][3] : 0;
  a09=casadi_sq(a08);
  a07=(a07+a09);
  a03=casadi_fmax(a03,a07);
  a07=sqrt(a03);
  a07=(a01+a07);
  a07=(a07-a05);
  a09=(a00<a07);
  a10=1.3333333333333333e+00;
  a11=(a05*a01);
  a05=(a05-a01);
  a11=(a11/a05);
  a11=sqrt(a11);
  a11=(a10*a11);
  a05=1.;
  a01=arg[1]? arg[1][23] : 0;
  a01=casadi_sq(a01);
  a01=(a05-a01);
  a12=arg[1]? arg[1][22] : 0;
  a01=(a01/a12);
  a12=arg[1]? arg[1][25] : 0;
  a12=casadi_sq(a12);
  a12=(a05-a12);
  a13=arg[1]? arg[1][24] : 0;
  a12=(a12/a13);
  a01=(a01+a12);
  a11=(a11/a01);
  a01=7.5000000000000000e-01;
  a12=-7.5000000000000000e-01;
  a13=arg[1]? arg[1][34] : 0;
  a13=casadi_sq(a13);
  a12=(a12*a13);
  a01=(a01+a12);
  a12=arg[2]? arg[2][0] : 0;
  a13=arg[1]? arg[1][35] : 0;
  a12=casadi_fmax(a12,a13);
  a12=(a01/a12);
  a14=-5.0000000000000000e-01;
  a03=pow(a03,a14);
  a06=(a03*a06);
  a15=arg[0]? arg[0][8] : 0;
  a06=(a06*a15);
  a03=(a03*a08);
  a08=arg[0]? arg[0][9] : 0;
  a03=(a03*a08);
  a06=(a06+a03);
  a12=(a12*a06);
  a12=(a05+a12);
  a11=(a11*a12);
  a12=1.0000000000000000e-300;
  a07=casadi_fmax(a12,a07);
  a06=arg[1]? arg[1][33] : 0;
  a07=pow(a07,a06);
  a11=(a11*a07);
  a09=(a09?a11:0);
  a09=casadi_fmax(a00,a09);
  if (res[0]!=0) res[0][0]=a09;
  a09=arg[1]? arg[1][27] : 0;
  a02=(a02*a09);
  a11=arg[1]? arg[1][26] : 0;
  a04=(a04*a11);
  a02=(a02+a04);
  a02=casadi_sq(a02);
  a04=arg[0]? arg[0][4] : 0;
  a07=casadi_sq(a04);
  a03=arg[0]? arg[0][5] : 0;
  a08=casadi_sq(a03);
  a07=(a07+a08);
  a02=casadi_fmax(a02,a07);
  a07=sqrt(a02);
  a07=(a09+a07);
  a07=(a07-a11);
  a08=(a00<a07);
  a15=(a11*a09);
  a11=(a11-a09);
  a15=(a15/a11);
  a15=sqrt(a15);
  a10=(a10*a15);
  a15=arg[1]? arg[1][29] : 0;
  a15=casadi_sq(a15);
  a15=(a05-a15);
  a11=arg[1]? arg[1][28] : 0;
  a15=(a15/a11);
  a11=arg[1]? arg[1][31] : 0;
  a11=casadi_sq(a11);
  a11=(a05-a11);
  a09=arg[1]? arg[1][30] : 0;
  a11=(a11/a09);
  a15=(a15+a11);
  a10=(a10/a15);
  a15=arg[2]? arg[2][1] : 0;
  a15=casadi_fmax(a15,a13);
  a01=(a01/a15);
  a02=pow(a02,a14);
  a04=(a02*a04);
  a14=arg[0]? arg[0][10] : 0;
  a04=(a04*a14);
  a02=(a02*a03);
  a03=arg[0]? arg[0][11] : 0;
  a02=(a02*a03);
  a04=(a04+a02);
  a01=(a01*a04);
  a05=(a05+a01);
  a10=(a10*a05);
  a12=casadi_fmax(a12,a07);
  a12=pow(a12,a06);
  a10=(a10*a12);
  a08=(a08?a10:0);
  a00=casadi_fmax(a00,a08);
  if (res[0]!=0) res[0][1]=a00;
  return 0;
}

CASADI_SYMBOL_EXPORT int normal_force(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f6(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int normal_force_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void normal_force_release(int mem) {
}

CASADI_SYMBOL_EXPORT void normal_force_incref(void) {
}

CASADI_SYMBOL_EXPORT void normal_force_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int normal_force_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int normal_force_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real normal_force_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* normal_force_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "p";
    case 2: return "v_imp";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* normal_force_name_out(casadi_int i) {
  switch (i) {
    case 0: return "f_n";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* normal_force_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s1;
    case 2: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* normal_force_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int normal_force_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int normal_force_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* energy:(x[12],p[39])->(kinetic,gravity,contact,total) */
static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27;
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
  a12=(a11*a02);
  a13=arg[0]? arg[0][9] : 0;
  a12=(a12+a13);
  a12=casadi_sq(a12);
  a14=arg[0]? arg[0][8] : 0;
  a15=sin(a09);
  a06=(a06*a15);
  a16=(a06*a02);
  a16=(a14-a16);
  a16=casadi_sq(a16);
  a12=(a12+a16);
  a05=(a05*a12);
  a01=(a01+a05);
  a05=arg[1]? arg[1][9] : 0;
  a12=(a00*a05);
  a16=arg[1]? arg[1][4] : 0;
  a10=(a16*a10);
  a17=(a10*a02);
  a18=arg[1]? arg[1][11] : 0;
  a19=(a18*a04);
  a20=arg[0]? arg[0][1] : 0;
  a09=(a09+a20);
  a21=cos(a09);
  a22=(a19*a21);
  a22=(a17+a22);
  a22=(a22+a13);
  a23=arg[0]? arg[0][11] : 0;
  a22=(a22+a23);
  a22=casadi_sq(a22);
  a16=(a16*a15);
  a02=(a16*a02);
  a09=sin(a09);
  a19=(a19*a09);
  a19=(a02+a19);
  a19=(a14-a19);
  a15=arg[0]? arg[0][10] : 0;
  a19=(a19+a15);
  a19=casadi_sq(a19);
  a22=(a22+a19);
  a12=(a12*a22);
  a01=(a01+a12);
  a12=arg[1]? arg[1][13] : 0;
  a22=(a00*a12);
  a19=arg[1]? arg[1][8] : 0;
  a24=(a19*a04);
  a25=(a24*a21);
  a17=(a17+a25);
  a25=arg[1]? arg[1][15] : 0;
  a26=(a25*a04);
  a27=arg[1]? arg[1][32] : 0;
  a27=(a07+a27);
  a27=(a27+a08);
  a27=(a27+a20);
  a20=cos(a27);
  a08=(a26*a20);
  a08=(a17+a08);
  a08=(a08+a13);
  a08=(a08+a23);
  a08=casadi_sq(a08);
  a24=(a24*a09);
  a02=(a02+a24);
  a27=sin(a27);
  a26=(a26*a27);
  a26=(a02+a26);
  a26=(a14-a26);
  a26=(a26+a15);
  a26=casadi_sq(a26);
  a08=(a08+a26);
  a22=(a22*a08);
  a01=(a01+a22);
  a22=arg[1]? arg[1][16] : 0;
  a00=(a00*a22);
  a08=arg[1]? arg[1][12] : 0;
  a04=(a08*a04);
  a26=(a04*a20);
  a17=(a17+a26);
  a17=(a17+a13);
  a17=(a17+a23);
  a17=casadi_sq(a17);
  a04=(a04*a27);
  a02=(a02+a04);
  a14=(a14-a02);
  a14=(a14+a15);
  a14=casadi_sq(a14);
  a17=(a17+a14);
  a00=(a00*a17);
  a01=(a01+a00);
  if (res[0]!=0) res[0][0]=a01;
  a00=arg[1]? arg[1][1] : 0;
  a17=arg[1]? arg[1][3] : 0;
  a14=arg[1]? arg[1][17] : 0;
  a15=(a17*a14);
  a02=cos(a07);
  a15=(a15*a02);
  a04=arg[1]? arg[1][18] : 0;
  a17=(a17*a04);
  a07=sin(a07);
  a17=(a17*a07);
  a15=(a15+a17);
  a00=(a00*a15);
  a15=arg[1]? arg[1][0] : 0;
  a02=(a15*a02);
  a11=(a02+a11);
  a17=arg[0]? arg[0][2] : 0;
  a11=(a11+a17);
  a11=(a14*a11);
  a15=(a15*a07);
  a06=(a15+a06);
  a07=arg[0]? arg[0][3] : 0;
  a06=(a06+a07);
  a06=(a04*a06);
  a11=(a11+a06);
  a03=(a03*a11);
  a00=(a00+a03);
  a02=(a02+a10);
  a10=(a18*a21);
  a10=(a02+a10);
  a10=(a10+a17);
  a03=arg[0]? arg[0][4] : 0;
  a10=(a10+a03);
  a10=(a14*a10);
  a15=(a15+a16);
  a18=(a18*a09);
  a18=(a15+a18);
  a18=(a18+a07);
  a16=arg[0]? arg[0][5] : 0;
  a18=(a18+a16);
  a18=(a04*a18);
  a10=(a10+a18);
  a05=(a05*a10);
  a00=(a00+a05);
  a21=(a19*a21);
  a02=(a02+a21);
  a21=(a25*a20);
  a21=(a02+a21);
  a21=(a21+a17);
  a21=(a21+a03);
  a21=(a14*a21);
  a19=(a19*a09);
  a15=(a15+a19);
  a25=(a25*a27);
  a25=(a15+a25);
  a25=(a25+a07);
  a25=(a25+a16);
  a25=(a04*a25);
  a21=(a21+a25);
  a12=(a12*a21);
  a00=(a00+a12);
  a20=(a08*a20);
  a02=(a02+a20);
  a02=(a02+a17);
  a02=(a02+a03);
  a14=(a14*a02);
  a08=(a08*a27);
  a15=(a15+a08);
  a15=(a15+a07);
  a15=(a15+a16);
  a04=(a04*a15);
  a14=(a14+a04);
  a22=(a22*a14);
  a00=(a00+a22);
  a22=(-a00);
  if (res[1]!=0) res[1][0]=a22;
  a22=0.;
  a14=arg[1]? arg[1][21] : 0;
  a04=-9.9999999999999995e-07;
  a15=(a04*a14);
  a08=9.9999999999999995e-07;
  a27=arg[1]? arg[1][20] : 0;
  a02=(a08*a27);
  a15=(a15+a02);
  a15=casadi_sq(a15);
  a17=casadi_sq(a17);
  a07=casadi_sq(a07);
  a17=(a17+a07);
  a15=casadi_fmax(a15,a17);
  a15=sqrt(a15);
  a15=(a14+a15);
  a15=(a15-a27);
  a17=(a22<a15);
  a07=1.3333333333333333e+00;
  a02=(a27*a14);
  a27=(a27-a14);
  a02=(a02/a27);
  a02=sqrt(a02);
  a02=(a07*a02);
  a27=1.;
  a14=arg[1]? arg[1][33] : 0;
  a14=(a27+a14);
  a02=(a02/a14);
  a20=arg[1]? arg[1][23] : 0;
  a20=casadi_sq(a20);
  a20=(a27-a20);
  a12=arg[1]? arg[1][22] : 0;
  a20=(a20/a12);
  a12=arg[1]? arg[1][25] : 0;
  a12=casadi_sq(a12);
  a12=(a27-a12);
  a21=arg[1]? arg[1][24] : 0;
  a12=(a12/a21);
  a20=(a20+a12);
  a02=(a02/a20);
  a20=1.0000000000000000e-300;
  a15=casadi_fmax(a20,a15);
  a15=pow(a15,a14);
  a02=(a02*a15);
  a17=(a17?a02:0);
  a02=arg[1]? arg[1][27] : 0;
  a04=(a04*a02);
  a15=arg[1]? arg[1][26] : 0;
  a08=(a08*a15);
  a04=(a04+a08);
  a04=casadi_sq(a04);
  a03=casadi_sq(a03);
  a16=casadi_sq(a16);
  a03=(a03+a16);
  a04=casadi_fmax(a04,a03);
  a04=sqrt(a04);
  a04=(a02+a04);
  a04=(a04-a15);
  a22=(a22<a04);
  a03=(a15*a02);
  a15=(a15-a02);
  a03=(a03/a15);
  a03=sqrt(a03);
  a07=(a07*a03);
  a07=(a07/a14);
  a03=arg[1]? arg[1][29] : 0;
  a03=casadi_sq(a03);
  a03=(a27-a03);
  a15=arg[1]? arg[1][28] : 0;
  a03=(a03/a15);
  a15=arg[1]? arg[1][31] : 0;
  a15=casadi_sq(a15);
  a27=(a27-a15);
  a15=arg[1]? arg[1][30] : 0;
  a27=(a27/a15);
  a03=(a03+a27);
  a07=(a07/a03);
  a20=casadi_fmax(a20,a04);
  a20=pow(a20,a14);
  a07=(a07*a20);
  a22=(a22?a07:0);
  a17=(a17+a22);
  if (res[2]!=0) res[2][0]=a17;
  a01=(a01-a00);
  a01=(a01+a17);
  if (res[3]!=0) res[3][0]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f7(arg, res, iw, w, mem);
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
    case 0: return casadi_s11;
    case 1: return casadi_s11;
    case 2: return casadi_s11;
    case 3: return casadi_s11;
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
static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18;
  a00=arg[2]? arg[2][0] : 0;
  a01=arg[2]? arg[2][19] : 0;
  a02=cos(a01);
  a02=(a00*a02);
  a03=arg[2]? arg[2][4] : 0;
  a04=arg[0]? arg[0][0] : 0;
  a05=(a01+a04);
  a06=cos(a05);
  a07=(a03*a06);
  a02=(a02+a07);
  a07=arg[2]? arg[2][8] : 0;
  a08=arg[0]? arg[0][1] : 0;
  a09=(a05+a08);
  a10=cos(a09);
  a11=(a07*a10);
  a02=(a02+a11);
  a11=arg[2]? arg[2][12] : 0;
  a12=arg[2]? arg[2][32] : 0;
  a12=(a01+a12);
  a12=(a12+a04);
  a12=(a12+a08);
  a08=cos(a12);
  a04=(a11*a08);
  a02=(a02+a04);
  a04=arg[0]? arg[0][2] : 0;
  a02=(a02+a04);
  a04=arg[0]? arg[0][4] : 0;
  a02=(a02+a04);
  if (res[0]!=0) res[0][0]=a02;
  a01=sin(a01);
  a00=(a00*a01);
  a05=sin(a05);
  a01=(a03*a05);
  a00=(a00+a01);
  a09=sin(a09);
  a01=(a07*a09);
  a00=(a00+a01);
  a12=sin(a12);
  a01=(a11*a12);
  a00=(a00+a01);
  a01=arg[0]? arg[0][3] : 0;
  a00=(a00+a01);
  a01=arg[0]? arg[0][5] : 0;
  a00=(a00+a01);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[0]? arg[0][8] : 0;
  a01=arg[0]? arg[0][6] : 0;
  a02=(a05*a01);
  a04=(a03*a02);
  a13=arg[0]? arg[0][7] : 0;
  a13=(a01+a13);
  a14=(a09*a13);
  a15=(a07*a14);
  a04=(a04+a15);
  a15=(a12*a13);
  a16=(a11*a15);
  a04=(a04+a16);
  a00=(a00-a04);
  a04=arg[0]? arg[0][10] : 0;
  a00=(a00+a04);
  if (res[1]!=0) res[1][0]=a00;
  a00=(a06*a01);
  a04=(a03*a00);
  a16=(a10*a13);
  a17=(a07*a16);
  a04=(a04+a17);
  a17=(a08*a13);
  a18=(a11*a17);
  a04=(a04+a18);
  a18=arg[0]? arg[0][9] : 0;
  a04=(a04+a18);
  a18=arg[0]? arg[0][11] : 0;
  a04=(a04+a18);
  if (res[1]!=0) res[1][1]=a04;
  a04=arg[1]? arg[1][2] : 0;
  a00=(a01*a00);
  a18=arg[1]? arg[1][0] : 0;
  a05=(a05*a18);
  a00=(a00+a05);
  a00=(a03*a00);
  a16=(a13*a16);
  a05=arg[1]? arg[1][1] : 0;
  a05=(a18+a05);
  a09=(a09*a05);
  a16=(a16+a09);
  a16=(a07*a16);
  a00=(a00+a16);
  a17=(a13*a17);
  a12=(a12*a05);
  a17=(a17+a12);
  a17=(a11*a17);
  a00=(a00+a17);
  a04=(a04-a00);
  a00=arg[1]? arg[1][4] : 0;
  a04=(a04+a00);
  if (res[2]!=0) res[2][0]=a04;
  a06=(a06*a18);
  a01=(a01*a02);
  a06=(a06-a01);
  a03=(a03*a06);
  a10=(a10*a05);
  a14=(a13*a14);
  a10=(a10-a14);
  a07=(a07*a10);
  a03=(a03+a07);
  a08=(a08*a05);
  a13=(a13*a15);
  a08=(a08-a13);
  a11=(a11*a08);
  a03=(a03+a11);
  a11=arg[1]? arg[1][3] : 0;
  a03=(a03+a11);
  a11=arg[1]? arg[1][5] : 0;
  a03=(a03+a11);
  if (res[2]!=0) res[2][1]=a03;
  return 0;
}

CASADI_SYMBOL_EXPORT int end_effector(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f8(arg, res, iw, w, mem);
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
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i;
  casadi_real **res1=res+1, *rr, *w00=w+159, w01, w02, *w03=w+171, *w04=w+177, *w06=w+179, *w07=w+181, w08, *w09=w+193, *w10=w+205;
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
  for (i=0, rr=w10, cs=w10; i<12; ++i) (*rr++)  = (w08*(*cs++));
  for (i=0, rr=w10, cr=wr00, cs=w10; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
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
  return casadi_f9(arg, res, iw, w, mem);
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
    case 1: return casadi_s12;
    case 2: return casadi_s11;
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
  if (sz_w) *sz_w = 217;
  return 0;
}

CASADI_SYMBOL_EXPORT int rk4_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 217*sizeof(casadi_real);
  return 0;
}

/* radau_step:(x[12],tau_stages[2x3],h,p[39],v_imp[2])->(x_next[12],newton_increment) */
static int casadi_f10(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_int i, j;
  casadi_real *qr_beta, *qr_r, *qr_v, *qr_w, **res1=res+2, *rr, *w00=w+564, *w01=w+576, w02, *w04=w+594, *w05=w+600, *w06=w+654;
  casadi_real *w07=w+978, *w09=w+980, *w10=w+982, *w11=w+1060, *w12=w+1096, w13, *w15=w+1420, *w16=w+1744, *w17=w+1780, *w18=w+1792, *w19=w+1794, *w20=w+1806;
  casadi_real *w21=w+1808, *w22=w+1820, *w23=w+1856, *w24=w+1892, *w25=w+1910, *w26=w+1928, *w27=w+1946;
  const casadi_real **arg1=arg+5, *cr, *cs, *ct, *ss, *wr00, *wr03, *wr06, *wr08, *wr14;
  wr00 = arg[0] ? arg[0] : casadi_zeros;
  casadi_clear(w01, 18);
  w02 = arg[2] ? arg[2][0] : 0;
  wr03 = casadi_c0;
  casadi_fill(w04, 6, 1.);
  casadi_kron_dense_sparse(wr03, 3, 3, w04, casadi_s13, w05);
  for (i=0, rr=w05, cs=w05; i<54; ++i) (*rr++)  = (w02*(*cs++));
  wr06 = casadi_c1;
  casadi_copy(arg[1], 6, w04);
  for (rr=w07, cs=w04+0; cs!=w04+2; cs+=1) *rr++ = *cs;
  wr08 = arg[3] ? arg[3] : casadi_zeros;
  casadi_copy(arg[4], 2, w09);
  arg1[0]=wr00;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w10;
  if (casadi_f3(arg1, res1, iw, w, 0)) return 1;
  for (rr=w11, cs=w10+0; cs!=w10+42; cs+=7) for (ct=cs+37; ct!=cs+43; ct+=1) *rr++ = *ct;
  casadi_kron_dense(wr03, 3, 3, w11, 6, 6, w12);
  for (i=0, rr=w12, cs=w12; i<324; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w12, cr=wr06, cs=w12; i<324; ++i) (*rr++)  = ((*cr++)-(*cs++));
  w13 = casadi_sq( w02 );
  wr14 = casadi_c2;
  for (rr=w11, cs=w10+0; cs!=w10+36; cs+=1) *rr++ = *cs;
  casadi_kron_dense(wr14, 3, 3, w11, 6, 6, w15);
  for (i=0, rr=w15, cs=w15; i<324; ++i) (*rr++)  = (w13*(*cs++));
  for (i=0, rr=w12, cs=w15; i<324; ++i) (*rr++) -= (*cs++);
  rr = w06;
  ss = w12;
  casadi_copy(wr06, 324, rr);
  qr_v = w;
  qr_r = w+171;
  qr_beta = w+342;
  qr_w = w+360;
  casadi_qr(casadi_s15, ss, qr_w, casadi_s16, qr_v, casadi_s17, qr_r, qr_beta, casadi_s14, casadi_s14);
  casadi_qr_solve(rr, 18, 0, casadi_s16, qr_v, casadi_s17, qr_r, qr_beta, casadi_s14, casadi_s14, qr_w);
  casadi_clear(w16, 36);
  arg1[0]=wr00;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w18, cs=w04+2; cs!=w04+4; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w20, cs=w04+4; cs!=w04+6; cs+=1) *rr++ = *cs;
  arg1[0]=wr00;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w21;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w22;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w21; i<12; ++i) *rr++ = *cs++;
  wr14 = casadi_c3;
  casadi_copy(w16, 36, w23);
  casadi_mtimes_dense(w22, 12, 3, wr14, 3, w23, 0);
  for (i=0, rr=w23, cs=w23; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w23, cs=w23; i<36; ++i) *rr++ = (- *cs++ );
  for (rr=w24, cs=w23+0; cs!=w23+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  casadi_kron_dense(wr03, 3, 3, w11, 6, 6, w12);
  for (i=0, rr=w12, cs=w12; i<324; ++i) (*rr++)  = (w02*(*cs++));
  for (rr=w25, cs=w23+0; cs!=w23+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w24, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_copy(w01, 18, w24);
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w24, casadi_s18, w, 0);
  for (i=0, rr=w24, cs=w25; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w25, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w24, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w23;
  for (i=0, cs=w25; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w11, cs=w23; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (rr=w17, cs=w11+0; cs!=w11+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w17;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w11+12; cs!=w11+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w17;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w21;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w17;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w27;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w23;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w21; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w27; i<12; ++i) *rr++ = *cs++;
  casadi_copy(w16, 36, w22);
  casadi_mtimes_dense(w23, 12, 3, wr14, 3, w22, 0);
  for (i=0, rr=w22, cs=w22; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w22, cr=w11, cs=w22; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w25, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  for (rr=w24, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w25, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_copy(w01, 18, w25);
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w25, casadi_s18, w, 0);
  for (i=0, rr=w25, cs=w24; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w24, cs=w25; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w25, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w22;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w25; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w23, cs=w22; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w11, cs=w23; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w19, cs=w11+0; cs!=w11+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w19;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w21;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w11+12; cs!=w11+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w19;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w27;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w19;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w23;
  for (i=0, cs=w21; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w27; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  casadi_copy(w16, 36, w22);
  casadi_mtimes_dense(w23, 12, 3, wr14, 3, w22, 0);
  for (i=0, rr=w22, cs=w22; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w22, cr=w11, cs=w22; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w24, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  for (rr=w25, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w24, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_copy(w01, 18, w24);
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w24, casadi_s18, w, 0);
  for (i=0, rr=w24, cs=w25; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w25, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w24, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w22;
  for (i=0, cs=w25; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w23, cs=w22; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w11, cs=w23; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w21, cs=w11+0; cs!=w11+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w21, cr=wr00, cs=w21; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w21;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w27;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w21, cs=w11+12; cs!=w11+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w21, cr=wr00, cs=w21; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w21;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w21, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w21, cr=wr00, cs=w21; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w21;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w23;
  for (i=0, cs=w27; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  casadi_copy(w16, 36, w22);
  casadi_mtimes_dense(w23, 12, 3, wr14, 3, w22, 0);
  for (i=0, rr=w22, cs=w22; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w22, cr=w11, cs=w22; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w25, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  for (rr=w24, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w25, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_copy(w01, 18, w25);
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w25, casadi_s18, w, 0);
  for (i=0, rr=w25, cs=w24; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w24, cs=w25; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w25, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w22;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w25; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w23, cs=w22; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w11, cs=w23; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w27, cs=w11+0; cs!=w11+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w27, cr=wr00, cs=w27; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w27;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w27, cs=w11+12; cs!=w11+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w27, cr=wr00, cs=w27; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w27;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w27, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w27, cr=wr00, cs=w27; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w27;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w21;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w23;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w21; i<12; ++i) *rr++ = *cs++;
  casadi_copy(w16, 36, w22);
  casadi_mtimes_dense(w23, 12, 3, wr14, 3, w22, 0);
  for (i=0, rr=w22, cs=w22; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w22, cr=w11, cs=w22; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w24, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  for (rr=w25, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w24, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_copy(w01, 18, w24);
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w24, casadi_s18, w, 0);
  for (i=0, rr=w24, cs=w25; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w25, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w24, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w22;
  for (i=0, cs=w25; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w23, cs=w22; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w11, cs=w23; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w17, cs=w11+0; cs!=w11+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w17;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w11+12; cs!=w11+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w17;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w21;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w17, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w17, cr=wr00, cs=w17; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w17;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w27;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w23;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w21; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w27; i<12; ++i) *rr++ = *cs++;
  casadi_copy(w16, 36, w22);
  casadi_mtimes_dense(w23, 12, 3, wr14, 3, w22, 0);
  for (i=0, rr=w22, cs=w22; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w22, cr=w11, cs=w22; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w25, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  for (rr=w24, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w25, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_copy(w01, 18, w25);
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w25, casadi_s18, w, 0);
  for (i=0, rr=w25, cs=w24; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w24, cs=w25; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w25, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w22;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w25; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w23, cs=w22; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w11, cs=w23; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w19, cs=w11+0; cs!=w11+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w19;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w21;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w11+12; cs!=w11+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w19;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w27;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w19, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w19, cr=wr00, cs=w19; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w19;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w23;
  for (i=0, cs=w21; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w27; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  casadi_copy(w16, 36, w22);
  casadi_mtimes_dense(w23, 12, 3, wr14, 3, w22, 0);
  for (i=0, rr=w22, cs=w22; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w22, cr=w11, cs=w22; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w24, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  for (rr=w25, cs=w22+0; cs!=w22+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w24, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_copy(w01, 18, w24);
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w24, casadi_s18, w, 0);
  for (i=0, rr=w24, cs=w25; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w25, cs=w24; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w24, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w22;
  for (i=0, cs=w25; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w23, cs=w22; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w11, cs=w23; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w21, cs=w11+0; cs!=w11+12; cs+=1) *rr++ = *cs;
  for (i=0, rr=w21, cr=wr00, cs=w21; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w21;
  arg1[1]=w07;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w27;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w21, cs=w11+12; cs!=w11+24; cs+=1) *rr++ = *cs;
  for (i=0, rr=w21, cr=wr00, cs=w21; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w21;
  arg1[1]=w18;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w17;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  for (rr=w21, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w21, cr=wr00, cs=w21; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  arg1[0]=w21;
  arg1[1]=w20;
  arg1[2]=wr08;
  arg1[3]=w09;
  res1[0]=w19;
  if (casadi_f2(arg1, res1, iw, w, 0)) return 1;
  rr=w23;
  for (i=0, cs=w27; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w17; i<12; ++i) *rr++ = *cs++;
  for (i=0, cs=w19; i<12; ++i) *rr++ = *cs++;
  casadi_mtimes_dense(w23, 12, 3, wr14, 3, w16, 0);
  for (i=0, rr=w16, cs=w16; i<36; ++i) (*rr++)  = (w02*(*cs++));
  for (i=0, rr=w16, cr=w11, cs=w16; i<36; ++i) (*rr++)  = ((*cr++)-(*cs++));
  for (rr=w25, cs=w16+0; cs!=w16+36; cs+=12) for (ct=cs+6; ct!=cs+12; ct+=1) *rr++ = *ct;
  for (rr=w24, cs=w16+0; cs!=w16+36; cs+=12) for (ct=cs+0; ct!=cs+6; ct+=1) *rr++ = *ct;
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w12, 18, 18, w24, 1, w26, 0);
  for (i=0, rr=w25, cs=w26; i<18; ++i) (*rr++) += (*cs++);
  casadi_copy(w01, 18, w26);
  casadi_mtimes_dense(w06, 18, 18, w25, 1, w26, 0);
  for (i=0, rr=w26, cs=w26; i<18; ++i) *rr++ = (- *cs++ );
  casadi_mtimes(w05, casadi_s19, w26, casadi_s18, w01, casadi_s18, w, 0);
  for (i=0, rr=w01, cs=w24; i<18; ++i) (*rr++) -= (*cs++);
  for (i=0, rr=w24, cs=w01; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  for (i=0, rr=w01, cs=w26; i<3; ++i) for (j=0; j<6; ++j) rr[i+j*3] = *cs++;
  rr=w16;
  for (i=0, cs=w24; i<18; ++i) *rr++ = *cs++;
  for (i=0, cs=w01; i<18; ++i) *rr++ = *cs++;
  for (i=0, rr=w23, cs=w16; i<12; ++i) for (j=0; j<3; ++j) rr[i+j*12] = *cs++;
  for (i=0, rr=w11, cs=w23; i<36; ++i) (*rr++) += (*cs++);
  for (rr=w27, cs=w11+24; cs!=w11+36; cs+=1) *rr++ = *cs;
  for (i=0, rr=w00, cr=wr00, cs=w27; i<12; ++i) (*rr++)  = ((*cr++)+(*cs++));
  casadi_copy(w00, 12, res[0]);
  w02 = casadi_norm_inf(36, w23);
  if (res[1]) res[1][0] = w02;
  return 0;
}

CASADI_SYMBOL_EXPORT int radau_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f10(arg, res, iw, w, mem);
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
    case 1: return casadi_s12;
    case 2: return casadi_s11;
    case 3: return casadi_s1;
    case 4: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* radau_step_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s11;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int radau_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 14;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 13;
  if (sz_w) *sz_w = 1958;
  return 0;
}

CASADI_SYMBOL_EXPORT int radau_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 14*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 13*sizeof(casadi_int);
  if (sz_w) *sz_w = 1958*sizeof(casadi_real);
  return 0;
}


