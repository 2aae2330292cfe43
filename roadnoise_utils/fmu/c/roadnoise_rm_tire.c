/* The moving-hub RM tire (Belluzzo et al. 2002, Eq. 5-7) as an FMI 2.0 co-simulation slave.

   One source for every tire: the tire's numbers are read at instantiation from
   resources/tire.bin, written by roadnoise_utils.fmu.tables (the layout is documented there).

   Inputs at each communication point t_k: the road heights at the footprint's leading edge,
   one per lateral strip (m), and the hub's vertical displacement (m). Outputs at t_k: the hub
   force F_M = F_F + F_H (N) and its two parts (Eq. 5). The road that has entered the footprint
   is kept as a delay line of the leading-edge heights; each tassello's displacement is a fixed
   weighted sum of it (the footprint's averaging kernels for a road linear between samples).
   Every modal section is stepped by its exact first-order-hold recursion
       x_k = e x_{k-1} + b0 v_{k-1} + b1 v_k,   output factor * Re(x_k),
   which needs the input at t_k: the outputs at t_k depend on the inputs set at t_k (direct
   feedthrough). A master sets the inputs, reads the outputs, then calls fmi2DoStep.

   The start: the FMU starts in the steady state of the inputs set at its first point (the road
   behind the leading edge level with its first height, every section at x = (b0 + b1) v / (1 - e)),
   so inputs held constant give the static force from the first point on, without a transient. */

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

/* A resource URI's path starts with a drive letter ("file:///C:/a" -> "C:/a") on Windows only; a POSIX
   path such as "/a:b" keeps its slash. Defined to 1 or 0 from outside to test either rule anywhere. */
#ifndef ROADNOISE_DRIVE_LETTERS
#ifdef _WIN32
#define ROADNOISE_DRIVE_LETTERS 1
#else
#define ROADNOISE_DRIVE_LETTERS 0
#endif
#endif

#ifdef _WIN32
#include <windows.h>
/* the path is UTF-8 (the URI's %-escapes decoded); Windows opens it through its wide-character API */
static FILE *open_file(const char *path) {
    wchar_t wide[4096];
    if (MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, path, -1, wide, 4096) == 0) return NULL;
    return _wfopen(wide, L"rb");
}
#else
static FILE *open_file(const char *path) { return fopen(path, "rb"); }
#endif

#include "roadnoise_rm_tire.h"

void roadnoise_log_message(Tire *tire, fmi2Status status, const char *category, const char *format, ...) {
    char message[1024], escaped[2048];
    size_t i, n = 0;
    va_list args;
    if (tire == NULL || tire->callbacks == NULL || tire->callbacks->logger == NULL) return;
    if (status == fmi2OK && !tire->logging) return;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    /* the message is passed as the logger's format: a '%' doubled reads as itself whether or not it formats */
    for (i = 0; message[i] && n + 2 < sizeof escaped; i++) {
        if (message[i] == '%') escaped[n++] = '%';
        escaped[n++] = message[i];
    }
    escaped[n] = 0;
    tire->callbacks->logger(tire->callbacks->componentEnvironment, tire->instance_name, status, category, escaped);
}


/* ---- reading tire.bin ---------------------------------------------------------------- */

static int read_block(FILE *file, void *out, size_t size, size_t count) {
    return fread(out, size, count, file) == count;
}

static double *read_doubles(FILE *file, size_t count, int *ok) {
    double *out = (double *)calloc(count > 0 ? count : 1, sizeof(double));
    if (out == NULL || !read_block(file, out, sizeof(double), count)) *ok = 0;
    return out;
}

static int *read_ints(FILE *file, size_t count, int *ok) {
    int *out = (int *)calloc(count > 0 ? count : 1, sizeof(int));
    if (out == NULL || !read_block(file, out, sizeof(int), count)) *ok = 0;
    return out;
}

static int is_drive(const char *p) { /* "C:" or "C%3A" */
    return isalpha((unsigned char)p[0]) &&
           (p[1] == ':' || (p[1] == '%' && p[2] == '3' && (p[3] == 'A' || p[3] == 'a')));
}

/* The resource location, a file URI (FMI 2.0 section 2.1.7), as a path: "file:///a/b%20c" -> "/a/b c"; on
   Windows "file:///C:/a", "file://localhost/C:/a" and the malformed "file://C:/a" -> "C:/a". A '%' not
   followed by two hex digits is kept as it is. Returns 0 if the path does not fit in size bytes. */
static int uri_to_path(const char *uri, char *path, size_t size) {
    size_t n = 0;
    const char *p = uri;
    if (strncmp(p, "file://localhost/", 17) == 0) p += 16;
    else if (strncmp(p, "file:///", 8) == 0) p += 7;
    else if (ROADNOISE_DRIVE_LETTERS && strncmp(p, "file://", 7) == 0 && is_drive(p + 7)) p += 7;
    else if (strncmp(p, "file:/", 6) == 0) p += 5;
    if (ROADNOISE_DRIVE_LETTERS && p[0] == '/' && is_drive(p + 1)) p++;
    while (*p && n + 1 < size) {
        if (p[0] == '%' && isxdigit((unsigned char)p[1]) && isxdigit((unsigned char)p[2])) {
            char hex[3] = {p[1], p[2], 0};
            path[n++] = (char)strtol(hex, NULL, 16);
            p += 3;
        } else {
            path[n++] = *p++;
        }
    }
    path[n] = 0;
    return *p == 0;
}

/* bytes of a tire.bin with these sizes (the layout of roadnoise_utils.fmu.tables), in double to stay exact */
static double file_bytes(const int *header) {
    double strips = header[1], tasselli = header[2], taps = header[3], sections = header[4], rows = header[5];
    return 8 + 6 * 4 + GUID_BYTES + 3 * 8 + 8 * strips + 8 * (tasselli + 1) + 2 * 4 * rows + 8 * rows * taps +
           4 * sections + 7 * 8 * sections + 8;
}

static const char *check_tire(const Tire *tire) {
    int r, s;
    if (!(tire->dt > 0) || !(tire->speed > 0) || !isfinite(tire->dt) || !isfinite(tire->speed) ||
        !isfinite(tire->leading_edge))
        return "resources/tire.bin: time step and speed must be finite and > 0";
    for (r = 0; r < tire->n_rows; r++)
        if (tire->row_strip[r] < 0 || tire->row_strip[r] >= tire->n_strips || tire->row_tassello[r] < 0 ||
            tire->row_tassello[r] >= tire->n_tasselli)
            return "resources/tire.bin: a tap row names a strip or tassello out of range";
    for (r = 1; r < tire->n_rows; r++)
        if (tire->row_strip[r] < tire->row_strip[r - 1] || tire->row_strip[r] > tire->row_strip[r - 1] + 1)
            return "resources/tire.bin: the tap rows are not in the order of their strips, or a road input drives "
                   "no tassello";
    if (tire->row_strip[0] != 0 || tire->row_strip[tire->n_rows - 1] != tire->n_strips - 1)
        return "resources/tire.bin: a road input drives no tassello";
    for (s = 0; s < tire->n_sections; s++) {
        if (tire->source[s] < 0 || tire->source[s] > tire->n_tasselli)
            return "resources/tire.bin: a section names an input out of range";
        if (!(hypot(tire->e_re[s], tire->e_im[s]) < 1.0))
            return "resources/tire.bin: a section is not stable (|e| >= 1)";
    }
    return NULL;
}

static const char *load_tire(Tire *tire, const char *resources, const char *guid) {
    char path[4096], magic[8], end[8], stored_guid[GUID_BYTES + 1];
    int header[6], ok = 1;
    long length;
    double numbers[3];
    FILE *file;
    if (!uri_to_path(resources, path, sizeof path - 16)) return "the resource location is too long";
    strcat(path, "/tire.bin");
    file = open_file(path);
    if (file == NULL) return "cannot open resources/tire.bin";
    if (fseek(file, 0, SEEK_END) != 0 || (length = ftell(file)) < 0 || fseek(file, 0, SEEK_SET) != 0) {
        fclose(file);
        return "cannot read resources/tire.bin";
    }
    if (!read_block(file, magic, 1, 8) || memcmp(magic, "RNTIRE\0\0", 8) != 0) {
        fclose(file);
        return "resources/tire.bin is not a roadnoise tire file (wrong magic)";
    }
    if (!read_block(file, header, sizeof(int), 6) || header[0] != FORMAT_VERSION) {
        fclose(file);
        return "resources/tire.bin has another format version";
    }
    tire->n_strips = header[1];
    tire->n_tasselli = header[2];
    tire->n_taps = header[3];
    tire->n_sections = header[4];
    tire->n_rows = header[5];
    if (tire->n_strips < 1 || tire->n_tasselli < 1 || tire->n_taps < 1 || tire->n_sections < 0 || tire->n_rows < 1 ||
        tire->n_strips > 1000 || tire->n_tasselli > 100000 || tire->n_taps > 1000000 || tire->n_sections > 10000000 ||
        tire->n_rows > 10000000 || tire->n_rows < tire->n_strips) { /* every strip drives a tap row */
        fclose(file);
        return "resources/tire.bin has sizes out of range";
    }
    /* before any allocation: with every strip in a tap row, the largest array (the delay line, 16 n_strips n_taps
       bytes) is at most twice the file's length, so a damaged header cannot ask for much more than the file */
    if (file_bytes(header) != (double)length) {
        fclose(file);
        return "resources/tire.bin is truncated or damaged (its length is not what its header announces)";
    }
    stored_guid[GUID_BYTES] = 0;
    if (!read_block(file, stored_guid, 1, GUID_BYTES) || guid == NULL || strcmp(stored_guid, guid) != 0) {
        fclose(file);
        return "resources/tire.bin belongs to another FMU (its GUID is not the model description's)";
    }
    if (!read_block(file, numbers, sizeof(double), 3)) ok = 0;
    tire->dt = numbers[0];
    tire->speed = numbers[1];
    tire->leading_edge = numbers[2];
    tire->strip_y = read_doubles(file, tire->n_strips, &ok);
    tire->direct = read_doubles(file, tire->n_tasselli + 1, &ok);
    tire->row_strip = read_ints(file, tire->n_rows, &ok);
    tire->row_tassello = read_ints(file, tire->n_rows, &ok);
    tire->taps = read_doubles(file, (size_t)tire->n_rows * tire->n_taps, &ok);
    tire->source = read_ints(file, tire->n_sections, &ok);
    tire->e_re = read_doubles(file, tire->n_sections, &ok);
    tire->e_im = read_doubles(file, tire->n_sections, &ok);
    tire->b0_re = read_doubles(file, tire->n_sections, &ok);
    tire->b0_im = read_doubles(file, tire->n_sections, &ok);
    tire->b1_re = read_doubles(file, tire->n_sections, &ok);
    tire->b1_im = read_doubles(file, tire->n_sections, &ok);
    tire->factor = read_doubles(file, tire->n_sections, &ok);
    if (!ok || !read_block(file, end, 1, 8) || memcmp(end, "RNTIREND", 8) != 0) {
        fclose(file);
        return "resources/tire.bin is truncated or damaged";
    }
    fclose(file);
    return check_tire(tire);
}

/* ---- the tire's step ----------------------------------------------------------------- */

static void reset_state(Tire *tire) {
    int s;
    for (s = 0; s < tire->n_sections; s++) tire->x_re[s] = tire->x_im[s] = tire->v_prev[s] = 0.0;
    memset(tire->delay, 0, sizeof(double) * 2 * tire->n_strips * tire->n_taps);
    tire->pos = tire->n_taps;
    tire->n_committed = 0;
    tire->fresh = 0;
    tire->time = 0.0;
}

/* each strip's window: the heights m = 0 .. n_taps - 1 steps before the current point, the input now set
   first; before the first step the road behind is level with it (the window filled with it) */
static double *window(const Tire *tire, int strip) {
    return tire->delay + (size_t)strip * 2 * tire->n_taps + tire->pos;
}

static fmi2Status compute(Tire *tire) {
    int i, r, m, s;
    double fixed = 0.0, hub = 0.0;
    if (tire->fresh) return fmi2OK;
    for (s = 0; s < tire->n_strips; s++)
        if (!isfinite(tire->road[s]))
            FAIL(tire, "road_height[%d] = %g at t = %g s: the road must be finite (has the road ended?)", s + 1,
                 tire->road[s], tire->time);
    if (!isfinite(tire->hub)) FAIL(tire, "hub_displacement = %g at t = %g s: must be finite", tire->hub, tire->time);
    for (s = 0; s < tire->n_strips; s++) {
        double *w = window(tire, s);
        w[0] = tire->road[s];
        if (tire->n_committed == 0)
            for (m = 1; m < tire->n_taps; m++) w[m] = tire->road[s];
    }
    for (i = 0; i < tire->n_tasselli; i++) tire->u[i] = 0.0;
    for (r = 0; r < tire->n_rows; r++) {
        const double *taps = tire->taps + (size_t)r * tire->n_taps, *w = window(tire, tire->row_strip[r]);
        double sum[4] = {0.0, 0.0, 0.0, 0.0}; /* four chains: the additions overlap in the pipeline */
        for (m = 0; m + 4 <= tire->n_taps; m += 4) {
            sum[0] += taps[m] * w[m];
            sum[1] += taps[m + 1] * w[m + 1];
            sum[2] += taps[m + 2] * w[m + 2];
            sum[3] += taps[m + 3] * w[m + 3];
        }
        for (; m < tire->n_taps; m++) sum[0] += taps[m] * w[m];
        tire->u[tire->row_tassello[r]] += (sum[0] + sum[1]) + (sum[2] + sum[3]);
    }
    tire->u[tire->n_tasselli] = tire->hub;
    for (i = 0; i < tire->n_tasselli; i++) fixed += tire->direct[i] * tire->u[i];
    hub = tire->direct[tire->n_tasselli] * tire->hub;
    for (s = 0; s < tire->n_sections; s++) {
        double v = tire->u[tire->source[s]], re, im;
        if (tire->n_committed == 0) { /* the steady state of v: x = (b0 + b1) v / (1 - e) */
            double num_re = (tire->b0_re[s] + tire->b1_re[s]) * v, num_im = (tire->b0_im[s] + tire->b1_im[s]) * v;
            double den_re = 1.0 - tire->e_re[s], den_im = -tire->e_im[s], den = den_re * den_re + den_im * den_im;
            re = (num_re * den_re + num_im * den_im) / den;
            im = (num_im * den_re - num_re * den_im) / den;
        } else {
            re = tire->e_re[s] * tire->x_re[s] - tire->e_im[s] * tire->x_im[s] + tire->b0_re[s] * tire->v_prev[s] +
                 tire->b1_re[s] * v;
            im = tire->e_re[s] * tire->x_im[s] + tire->e_im[s] * tire->x_re[s] + tire->b0_im[s] * tire->v_prev[s] +
                 tire->b1_im[s] * v;
        }
        tire->x_new_re[s] = re;
        tire->x_new_im[s] = im;
        if (tire->source[s] == tire->n_tasselli) hub += tire->factor[s] * re;
        else fixed += tire->factor[s] * re;
    }
    if (!isfinite(fixed) || !isfinite(hub))
        FAIL(tire, "the hub force is not finite at t = %g s (F_F = %g N, F_H = %g N)", tire->time, fixed, hub);
    tire->fixed_hub_force = fixed;
    tire->hub_force = hub;
    tire->force = fixed + hub;
    tire->fresh = 1;
    return fmi2OK;
}

static void commit(Tire *tire) {
    int s;
    for (s = 0; s < tire->n_sections; s++) {
        tire->x_re[s] = tire->x_new_re[s];
        tire->x_im[s] = tire->x_new_im[s];
        tire->v_prev[s] = tire->u[tire->source[s]];
    }
    if (tire->pos == 0) { /* the windows reach the buffers' start: move them to the end (every n_taps steps) */
        for (s = 0; s < tire->n_strips; s++) {
            double *buffer = tire->delay + (size_t)s * 2 * tire->n_taps;
            memmove(buffer + tire->n_taps + 1, buffer, sizeof(double) * (tire->n_taps - 1));
        }
        tire->pos = tire->n_taps + 1;
    }
    tire->pos--; /* the heights now set become one step old */
    tire->n_committed++;
    tire->fresh = 0;
}

/* ---- FMI 2.0 ------------------------------------------------------------------------- */

static void free_tire(Tire *tire) {
    void *arrays[] = {tire->strip_y, tire->direct, tire->row_strip, tire->row_tassello, tire->taps, tire->source, tire->e_re,
                      tire->e_im, tire->b0_re, tire->b0_im, tire->b1_re, tire->b1_im, tire->factor, tire->x_re,
                      tire->x_im, tire->v_prev, tire->x_new_re, tire->x_new_im, tire->delay,
                      tire->road, tire->u, tire->instance_name};
    size_t k;
    for (k = 0; k < sizeof arrays / sizeof arrays[0]; k++) free(arrays[k]);
    free(tire);
}

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    (void)nCategories;
    (void)categories;
    ((Tire *)c)->logging = loggingOn;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    Tire *tire = (Tire *)calloc(1, sizeof(Tire));
    const char *problem;
    int n;
    (void)visible;
    if (tire == NULL) return NULL;
    tire->callbacks = functions;
    tire->logging = loggingOn;
    tire->instance_name = (char *)calloc(strlen(instanceName ? instanceName : "") + 1, 1);
    if (instanceName) strcpy(tire->instance_name, instanceName);
    if (fmuType != fmi2CoSimulation) {
        roadnoise_log_message(tire, fmi2Error, "logStatusError", "this FMU is for co-simulation only");
        free_tire(tire);
        return NULL;
    }
    if (fmuResourceLocation == NULL) {
        roadnoise_log_message(tire, fmi2Error, "logStatusError", "no resource location given");
        free_tire(tire);
        return NULL;
    }
    problem = load_tire(tire, fmuResourceLocation, fmuGUID);
    if (problem != NULL) {
        roadnoise_log_message(tire, fmi2Error, "logStatusError", "%s (resources at %s)", problem, fmuResourceLocation);
        free_tire(tire);
        return NULL;
    }
    n = tire->n_sections > 0 ? tire->n_sections : 1;
    tire->x_re = (double *)calloc(n, sizeof(double));
    tire->x_im = (double *)calloc(n, sizeof(double));
    tire->v_prev = (double *)calloc(n, sizeof(double));
    tire->x_new_re = (double *)calloc(n, sizeof(double));
    tire->x_new_im = (double *)calloc(n, sizeof(double));
    tire->delay = (double *)calloc((size_t)2 * tire->n_strips * tire->n_taps, sizeof(double));
    tire->road = (double *)calloc(tire->n_strips, sizeof(double));
    tire->u = (double *)calloc(tire->n_tasselli + 1, sizeof(double));
    if (!tire->x_re || !tire->x_im || !tire->v_prev || !tire->x_new_re || !tire->x_new_im || !tire->delay ||
        !tire->road || !tire->u) {
        roadnoise_log_message(tire, fmi2Error, "logStatusError", "out of memory");
        free_tire(tire);
        return NULL;
    }
    reset_state(tire);
    return tire;
}

void fmi2FreeInstance(fmi2Component c) {
    if (c != NULL) free_tire((Tire *)c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    ((Tire *)c)->time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    (void)c;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    ((Tire *)c)->initialised = 1;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    (void)c;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) { /* as after instantiation: the inputs back at their start values, 0 */
    Tire *tire = (Tire *)c;
    reset_state(tire);
    memset(tire->road, 0, sizeof(double) * tire->n_strips);
    tire->hub = 0.0;
    tire->initialised = 0;
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    Tire *tire = (Tire *)c;
    size_t k;
    for (k = 0; k < nvr; k++) {
        fmi2ValueReference ref = vr[k];
        if (ref <= VR_HUB_FORCE && compute(tire) != fmi2OK) return fmi2Error;
        if (ref == VR_FORCE) value[k] = tire->force;
        else if (ref == VR_FIXED_HUB_FORCE) value[k] = tire->fixed_hub_force;
        else if (ref == VR_HUB_FORCE) value[k] = tire->hub_force;
        else if (ref == VR_HUB_DISPLACEMENT) value[k] = tire->hub;
        else if (ref == VR_SPEED) value[k] = tire->speed;
        else if (ref == VR_STEP) value[k] = tire->dt;
        else if (ref == VR_LEADING_EDGE) value[k] = tire->leading_edge;
        else if (ref >= VR_ROAD && ref < VR_ROAD + (fmi2ValueReference)tire->n_strips) value[k] = tire->road[ref - VR_ROAD];
        else if (ref >= VR_ROAD_Y && ref < VR_ROAD_Y + (fmi2ValueReference)tire->n_strips)
            value[k] = tire->strip_y[ref - VR_ROAD_Y];
        else FAIL(tire, "no variable has value reference %u", ref);
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    Tire *tire = (Tire *)c;
    size_t k;
    for (k = 0; k < nvr; k++) {
        fmi2ValueReference ref = vr[k];
        if (ref == VR_HUB_DISPLACEMENT) tire->hub = value[k];
        else if (ref >= VR_ROAD && ref < VR_ROAD + (fmi2ValueReference)tire->n_strips) tire->road[ref - VR_ROAD] = value[k];
        else if (ref == VR_SPEED) {
            if (!(fabs(value[k] - tire->speed) <= 1e-9 * tire->speed))
                FAIL(tire, "speed = %g m/s: this FMU was exported for %g m/s only (the road's flow through the "
                     "footprint is built for one speed); export one for %g m/s", value[k], tire->speed, value[k]);
        } else if (ref == VR_STEP) {
            if (!(fabs(value[k] - tire->dt) <= STEP_TOLERANCE * tire->dt))
                FAIL(tire, "time_step = %g s: this FMU steps %g s exactly", value[k], tire->dt);
        } else if (ref == VR_LEADING_EDGE) {
            if (!(fabs(value[k] - tire->leading_edge) <= 1e-12))
                FAIL(tire, "leading_edge_x = %g m: fixed at %g m by the tire's footprint", value[k], tire->leading_edge);
        } else if (ref >= VR_ROAD_Y && ref < VR_ROAD_Y + (fmi2ValueReference)tire->n_strips) {
            if (!(fabs(value[k] - tire->strip_y[ref - VR_ROAD_Y]) <= 1e-12))
                FAIL(tire, "road_y[%u] = %g m: fixed at %g m by the tire's tread strips", ref - VR_ROAD_Y + 1, value[k],
                     tire->strip_y[ref - VR_ROAD_Y]);
        } else FAIL(tire, "value reference %u cannot be set (inputs: hub_displacement, road_height[k])", ref);
        tire->fresh = 0;
    }
    return fmi2OK;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    Tire *tire = (Tire *)c;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (!tire->initialised) FAIL(tire, "fmi2DoStep before fmi2ExitInitializationMode");
    if (!(fabs(communicationStepSize - tire->dt) <= STEP_TOLERANCE * tire->dt))
        FAIL(tire, "communication step %.9g s: this FMU steps %.9g s exactly (the exact discretisation of its "
             "modes and the road's advance of speed x step through the footprint are built for it)",
             communicationStepSize, tire->dt);
    if (!(fabs(currentCommunicationPoint - tire->time) <= STEP_TOLERANCE * tire->dt))
        FAIL(tire, "communication point %.9g s: the FMU is at %.9g s (it steps forward only)",
             currentCommunicationPoint, tire->time);
    if (compute(tire) != fmi2OK) return fmi2Error;
    commit(tire);
    tire->time = currentCommunicationPoint + communicationStepSize;
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    (void)c;
    return fmi2Error; /* every step completes before fmi2DoStep returns */
}
