#include "arkode_api.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>

namespace unfurl::sim {

namespace {

// ARKStep takes an explicit and an implicit part: all of f is implicit.
void* ark_create(ARKRhsFn f, double t0, N_Vector y0, SUNContext ctx) { return ARKStepCreate(nullptr, f, t0, y0, ctx); }
int ark_reinit(void* mem, ARKRhsFn f, double t0, N_Vector y0) { return ARKStepReInit(mem, nullptr, f, t0, y0); }

}  // namespace

const ArkodeApi& erk_api() {
  static const ArkodeApi api{false,
                             ERKStepCreate,
                             ERKStepReInit,
                             ERKStepFree,
                             ERKStepSetUserData,
                             ERKStepSetErrHandlerFn,
                             ERKStepSVtolerances,
                             ERKStepSetMaxNumSteps,
                             ERKStepSetStopTime,
                             ERKStepRootInit,
                             ERKStepSetRootDirection,
                             ERKStepSetNoInactiveRootWarn,
                             ERKStepEvolve,
                             ERKStepGetDky,
                             ERKStepGetRootInfo,
                             ERKStepGetCurrentTime,
                             ERKStepGetCurrentStep,
                             ERKStepGetLastStep,
                             ERKStepGetNumSteps,
                             ERKStepGetNumErrTestFails,
                             ERKStepGetReturnFlagName};
  return api;
}

const ArkodeApi& dirk_api() {
  static const ArkodeApi api{true,
                             ark_create,
                             ark_reinit,
                             ARKStepFree,
                             ARKStepSetUserData,
                             ARKStepSetErrHandlerFn,
                             ARKStepSVtolerances,
                             ARKStepSetMaxNumSteps,
                             ARKStepSetStopTime,
                             ARKStepRootInit,
                             ARKStepSetRootDirection,
                             ARKStepSetNoInactiveRootWarn,
                             ARKStepEvolve,
                             ARKStepGetDky,
                             ARKStepGetRootInfo,
                             ARKStepGetCurrentTime,
                             ARKStepGetCurrentStep,
                             ARKStepGetLastStep,
                             ARKStepGetNumSteps,
                             ARKStepGetNumErrTestFails,
                             ARKStepGetReturnFlagName};
  return api;
}

}  // namespace unfurl::sim
