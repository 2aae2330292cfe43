/* The FMI 2.0 co-simulation functions of features this FMU does not have (integer, boolean and string
   variables, FMU states, derivatives, asynchronous status): an error, or fmi2Discard for a status query. */

#include <stddef.h>

#include "roadnoise_rm_tire.h"

#define NOT_SUPPORTED(tire, name) FAIL((Tire *)(tire), "%s is not supported by this FMU", name)

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    (void)vr; (void)value;
    if (nvr == 0) return fmi2OK;
    NOT_SUPPORTED(c, "fmi2GetInteger");
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    (void)vr; (void)value;
    if (nvr == 0) return fmi2OK;
    NOT_SUPPORTED(c, "fmi2GetBoolean");
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    (void)vr; (void)value;
    if (nvr == 0) return fmi2OK;
    NOT_SUPPORTED(c, "fmi2GetString");
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    (void)vr; (void)value;
    if (nvr == 0) return fmi2OK;
    NOT_SUPPORTED(c, "fmi2SetInteger");
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    (void)vr; (void)value;
    if (nvr == 0) return fmi2OK;
    NOT_SUPPORTED(c, "fmi2SetBoolean");
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    (void)vr; (void)value;
    if (nvr == 0) return fmi2OK;
    NOT_SUPPORTED(c, "fmi2SetString");
}
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) { (void)FMUstate; NOT_SUPPORTED(c, "fmi2GetFMUstate"); }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) { (void)FMUstate; NOT_SUPPORTED(c, "fmi2SetFMUstate"); }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) { (void)FMUstate; NOT_SUPPORTED(c, "fmi2FreeFMUstate"); }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size) {
    (void)FMUstate; (void)size;
    NOT_SUPPORTED(c, "fmi2SerializedFMUstateSize");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[], size_t size) {
    (void)FMUstate; (void)serializedState; (void)size;
    NOT_SUPPORTED(c, "fmi2SerializeFMUstate");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate) {
    (void)serializedState; (void)size; (void)FMUstate;
    NOT_SUPPORTED(c, "fmi2DeSerializeFMUstate");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    (void)vUnknown_ref; (void)nUnknown; (void)vKnown_ref; (void)nKnown; (void)dvKnown; (void)dvUnknown;
    NOT_SUPPORTED(c, "fmi2GetDirectionalDerivative");
}
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    (void)vr; (void)nvr; (void)order; (void)value;
    NOT_SUPPORTED(c, "fmi2SetRealInputDerivatives");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    (void)vr; (void)nvr; (void)order; (void)value;
    NOT_SUPPORTED(c, "fmi2GetRealOutputDerivatives");
}
/* a status this FMU does not keep: fmi2Discard, as FMI 2.0 asks (section 4.2.3); every step completes in
   fmi2DoStep, so fmi2LastSuccessfulTime is the only status it answers */
#define NO_STATUS(tire, name)                                                                         \
    do {                                                                                              \
        roadnoise_log_message((Tire *)(tire), fmi2Discard, "logStatusDiscard", "%s: this FMU keeps no such status", name); \
        return fmi2Discard;                                                                           \
    } while (0)

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    (void)s; (void)value;
    NO_STATUS(c, "fmi2GetStatus");
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    if (s == fmi2LastSuccessfulTime) {
        *value = ((Tire *)c)->time;
        return fmi2OK;
    }
    NO_STATUS(c, "fmi2GetRealStatus");
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    (void)s; (void)value;
    NO_STATUS(c, "fmi2GetIntegerStatus");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    (void)s; (void)value;
    NO_STATUS(c, "fmi2GetBooleanStatus");
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    (void)s; (void)value;
    NO_STATUS(c, "fmi2GetStringStatus");
}
