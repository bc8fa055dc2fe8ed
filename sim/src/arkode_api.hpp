// The calls the ARKODE integrator makes, as one table per stepper: SUNDIALS
// 6 names them ERKStep... for the explicit stepper and ARKStep... for the
// implicit one, with the same arguments. Picking the table once keeps the
// integrator free of a switch at every call.
#pragma once

#include <arkode/arkode.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

namespace unfurl::sim {

struct ArkodeApi {
  bool implicit;
  void* (*create)(ARKRhsFn f, double t0, N_Vector y0, SUNContext ctx);
  int (*reinit)(void* mem, ARKRhsFn f, double t0, N_Vector y0);
  void (*free)(void** mem);
  int (*set_user_data)(void* mem, void* data);
  int (*set_err_handler)(void* mem, ARKErrHandlerFn handler, void* data);
  int (*sv_tolerances)(void* mem, double rtol, N_Vector atol);
  int (*set_max_num_steps)(void* mem, long steps);
  int (*set_stop_time)(void* mem, double t);
  int (*root_init)(void* mem, int n, ARKRootFn g);
  int (*set_root_direction)(void* mem, int* direction);
  int (*set_no_inactive_root_warn)(void* mem);
  int (*evolve)(void* mem, double t_out, N_Vector y, double* t, int task);
  int (*get_dky)(void* mem, double t, int k, N_Vector dky);
  int (*get_root_info)(void* mem, int* found);
  int (*get_current_time)(void* mem, double* t);
  int (*get_current_step)(void* mem, double* h);
  int (*get_last_step)(void* mem, double* h);
  int (*get_num_steps)(void* mem, long* steps);
  int (*get_num_err_test_fails)(void* mem, long* fails);
  char* (*get_return_flag_name)(long flag);
};

// The explicit (ERKStep) and the implicit (ARKStep, all of f implicit)
// stepper.
const ArkodeApi& erk_api();
const ArkodeApi& dirk_api();

}  // namespace unfurl::sim
