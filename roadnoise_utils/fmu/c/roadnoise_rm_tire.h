/* The tire's state and numbers, shared by roadnoise_rm_tire.c (the model) and fmi2_unsupported.c (the FMI 2.0
   functions this FMU answers with an error or fmi2Discard). */
#ifndef ROADNOISE_RM_TIRE_H
#define ROADNOISE_RM_TIRE_H

#include "fmi2Functions.h"

#define VR_FORCE 0
#define VR_FIXED_HUB_FORCE 1
#define VR_HUB_FORCE 2
#define VR_HUB_DISPLACEMENT 3
#define VR_SPEED 4
#define VR_STEP 5
#define VR_LEADING_EDGE 6
#define VR_ROAD 10
#define VR_ROAD_Y 100000
#define FORMAT_VERSION 2
#define GUID_BYTES 64
/* accepted departure of a communication step from the FMU's own, relative: a tool's round-off, not another step */
#define STEP_TOLERANCE 1e-6

typedef struct {
    /* the tire's numbers (tire.bin) */
    int n_strips, n_tasselli, n_taps, n_sections, n_rows;
    double dt, speed, leading_edge;
    double *strip_y;     /* n_strips: lateral position of each road input (m) */
    double *direct;      /* n_tasselli + 1: feedthrough of each tassello's displacement, then the hub's */
    int *row_strip, *row_tassello;
    double *taps;        /* n_rows x n_taps: weight of the strip's height m steps ago on the tassello */
    int *source;         /* n_sections: the input driving each section (n_tasselli: the hub) */
    double *e_re, *e_im, *b0_re, *b0_im, *b1_re, *b1_im, *factor;
    /* the state at the last committed point */
    double *x_re, *x_im, *v_prev;  /* per section: state and drive at t_{k-1} */
    double *x_new_re, *x_new_im;   /* per section: state at t_k for the inputs now set */
    double *delay;       /* n_strips x 2 n_taps: each strip's window of heights, newest first, at [pos, pos + n_taps) */
    int pos, n_committed;
    double *road;        /* n_strips: inputs now set */
    double hub;
    double *u;           /* n_tasselli + 1: tassello displacements and the hub's, at t_k */
    double force, fixed_hub_force, hub_force;
    int fresh;           /* outputs computed for the inputs now set */
    double time;
    int initialised;
    char *instance_name;
    const fmi2CallbackFunctions *callbacks;
    int logging;
} Tire;

/* report through the environment's logger (errors always, the rest only with debug logging on) */
void roadnoise_log_message(Tire *tire, fmi2Status status, const char *category, const char *format, ...);

#define FAIL(tire, ...)                                           \
    do {                                                          \
        roadnoise_log_message((tire), fmi2Error, "logStatusError", __VA_ARGS__); \
        return fmi2Error;                                         \
    } while (0)

#endif
