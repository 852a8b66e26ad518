#pragma once
// DeviceStepper, the time step with every particle array resident on one executor: the class
// (device_stepper_class.hpp says what a step does and what an executor provides) and the
// definitions of its phases, one file per part of the step.
#include "netsph/backend/device/device_stepper_bodies.hpp"
#include "netsph/backend/device/device_stepper_class.hpp"
#include "netsph/backend/device/device_stepper_integration.hpp"
#include "netsph/backend/device/device_stepper_open.hpp"
#include "netsph/backend/device/device_stepper_rates.hpp"
#include "netsph/backend/device/device_stepper_sampling.hpp"
#include "netsph/backend/device/device_stepper_sort.hpp"
