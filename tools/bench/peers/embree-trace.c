/*
 * embree-trace: Embree's trace of the rays of the dragon bench frame (scenes/bench-dragon.yaml),
 * the peer that goal names ("warm render at most 2x Embree's trace of the same rays").
 *
 * It loads an OBJ mesh (.obj or .obj.gz, read through zlib), adds a plane as a large quad of two
 * triangles, builds one Embree scene of both (timed apart), then per repetition:
 *   primary: one ray per pixel through the pixel centre, made exactly as raytracer.cameras.Pinhole
 *            makes it (image plane at distance 1, half-height tan(fov/2), (x + 0.5, y + 0.5), y
 *            down; computed in double, handed to Embree in float), closest hit (rtcIntersect1);
 *   shadow:  for each hit and each point light, when the light is on the side of the (flat,
 *            geometric) normal turned towards the viewer (our renderer traces no ray otherwise),
 *            one occlusion ray (rtcOccluded1) from the hit point, offset along that normal, to
 *            just short of the light (direction = light - origin, tfar = 1 - 1e-5).
 * on T OpenMP threads (rows handed out dynamically). The rays are made before the timed passes
 * (the primary rays' directions once, the shadow rays once from the hits of an untimed first
 * primary pass), so that the times are Embree's traversal and intersection (with the copy of each
 * ray into Embree's struct and of its result out). It prints the load, build and the median and
 * range of the trace times (primary, shadow, total) over the repetitions, and the counts (rays,
 * hits on the mesh and the plane, shadow rays, blocked) so that they can be checked against
 * `render scenes/bench-dragon.yaml --stats`.
 *
 * With --plane-apart the plane is not in Embree's scene: each primary ray's tfar is clipped to its
 * hit on the plane, computed apart (Embree then finds only mesh hits nearer than the floor), and a
 * shadow ray whose ends lie on opposite sides of the plane is blocked without a call. That is the
 * least work a tracer can do for this frame; the default, the plane as two triangles in Embree's
 * scene, leaves the whole visibility query to Embree, as our renderer's World search does its own.
 *
 * With --pfm FILE it also shades the frame as our ray-cast tracer does for matte materials and
 * point lights (ambient ka cd La + sum kd cd / pi * I c / r^2 * cos, background on a miss), outside
 * the timed part, and writes it as a PFM (bottom row first), to compare pixel by pixel with ours.
 *
 * Built against Embree 4 (default) or Embree 3 (-DEMBREE_MAJOR=3); see tools/bench/peers/setup.
 * Our own code: it uses only Embree's public C API.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <zlib.h>

#ifndef EMBREE_MAJOR
#define EMBREE_MAJOR 4
#endif
#if EMBREE_MAJOR >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

#define MAX_LIGHTS 8
#define PLANE_APART_ID 0xFFFFFFFEu /* a hit on the plane computed apart */
#define PI 3.14159265358979323846
#define DEGREES_TO_RADIANS 0.017453292519943295 /* Java's Math.toRadians */

typedef struct { double x, y, z; } V3;

static V3 v3(double x, double y, double z) { V3 r = {x, y, z}; return r; }
static V3 sub(V3 a, V3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static V3 add(V3 a, V3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static V3 scale(V3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static V3 cross(V3 a, V3 b) { return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static V3 normalize(V3 a) { double l = sqrt(dot(a, a)); return scale(a, 1 / l); }

typedef struct {
    const char *obj;
    int width, height, threads, reps, verbose;
    V3 eye, look, up;
    double fov;
    int has_plane, plane_apart;
    V3 plane_point, plane_normal;
    double plane_size;
    int nlights;
    V3 light[MAX_LIGHTS];
    double light_ls[MAX_LIGHTS];
    V3 light_color[MAX_LIGHTS];
    /* shading, for --pfm only */
    const char *pfm;
    double ambient;
    V3 background;
    double mesh_ka, mesh_kd, plane_ka, plane_kd;
    V3 mesh_color, plane_color;
    double shadow_eps;
} Options;

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void die(const char *msg, const char *arg) {
    fprintf(stderr, "embree-trace: %s%s%s\n", msg, arg ? ": " : "", arg ? arg : "");
    exit(2);
}

static V3 parse_v3(const char *s) {
    V3 r;
    if (sscanf(s, "%lf,%lf,%lf", &r.x, &r.y, &r.z) != 3) {
        die("expected x,y,z", s);
    }
    return r;
}

static void usage(void) {
    fprintf(stderr,
            "usage: embree-trace --obj MESH.obj[.gz] --size W,H --eye x,y,z --look-at x,y,z [--up x,y,z] --fov DEG\n"
            "       [--plane px,py,pz,nx,ny,nz [--plane-apart]] [--light x,y,z[,ls,r,g,b]]... [--threads T] [--reps N]\n"
            "       [--pfm OUT.pfm --ambient La --background r,g,b --mesh-material ka,kd,r,g,b --plane-material ka,kd,r,g,b]\n"
            "       [--shadow-eps E] [--verbose]\n");
    exit(2);
}

static void parse_material(const char *s, double *ka, double *kd, V3 *c) {
    if (sscanf(s, "%lf,%lf,%lf,%lf,%lf", ka, kd, &c->x, &c->y, &c->z) != 5) {
        die("expected ka,kd,r,g,b", s);
    }
}

static Options parse_args(int argc, char **argv) {
    Options o;
    memset(&o, 0, sizeof o);
    o.threads = 2;
    o.reps = 7;
    o.up = v3(0, 1, 0);
    o.plane_size = 1000;
    o.shadow_eps = 1e-6;
    o.mesh_ka = o.plane_ka = 0.25;
    o.mesh_kd = o.plane_kd = 0.75;
    o.mesh_color = o.plane_color = v3(1, 1, 1);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
#define NEED() do { if (!v) usage(); i++; } while (0)
        if (!strcmp(a, "--obj")) { NEED(); o.obj = v; }
        else if (!strcmp(a, "--size")) { NEED(); if (sscanf(v, "%d,%d", &o.width, &o.height) != 2) die("expected W,H", v); }
        else if (!strcmp(a, "--eye")) { NEED(); o.eye = parse_v3(v); }
        else if (!strcmp(a, "--look-at")) { NEED(); o.look = parse_v3(v); }
        else if (!strcmp(a, "--up")) { NEED(); o.up = parse_v3(v); }
        else if (!strcmp(a, "--fov")) { NEED(); o.fov = atof(v); }
        else if (!strcmp(a, "--plane")) {
            NEED();
            if (sscanf(v, "%lf,%lf,%lf,%lf,%lf,%lf", &o.plane_point.x, &o.plane_point.y, &o.plane_point.z,
                       &o.plane_normal.x, &o.plane_normal.y, &o.plane_normal.z) != 6) die("expected px,py,pz,nx,ny,nz", v);
            o.has_plane = 1;
        }
        else if (!strcmp(a, "--plane-size")) { NEED(); o.plane_size = atof(v); }
        else if (!strcmp(a, "--plane-apart")) { o.plane_apart = 1; }
        else if (!strcmp(a, "--light")) {
            NEED();
            if (o.nlights == MAX_LIGHTS) die("too many lights", v);
            V3 p, c = v3(1, 1, 1);
            double ls = 1;
            int n = sscanf(v, "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &p.x, &p.y, &p.z, &ls, &c.x, &c.y, &c.z);
            if (n != 3 && n != 7) die("expected x,y,z or x,y,z,ls,r,g,b", v);
            o.light[o.nlights] = p;
            o.light_ls[o.nlights] = ls;
            o.light_color[o.nlights] = c;
            o.nlights++;
        }
        else if (!strcmp(a, "--threads")) { NEED(); o.threads = atoi(v); }
        else if (!strcmp(a, "--reps")) { NEED(); o.reps = atoi(v); }
        else if (!strcmp(a, "--pfm")) { NEED(); o.pfm = v; }
        else if (!strcmp(a, "--ambient")) { NEED(); o.ambient = atof(v); }
        else if (!strcmp(a, "--background")) { NEED(); o.background = parse_v3(v); }
        else if (!strcmp(a, "--mesh-material")) { NEED(); parse_material(v, &o.mesh_ka, &o.mesh_kd, &o.mesh_color); }
        else if (!strcmp(a, "--plane-material")) { NEED(); parse_material(v, &o.plane_ka, &o.plane_kd, &o.plane_color); }
        else if (!strcmp(a, "--shadow-eps")) { NEED(); o.shadow_eps = atof(v); }
        else if (!strcmp(a, "--verbose")) { o.verbose = 1; }
        else usage();
#undef NEED
    }
    if (!o.obj || o.width <= 0 || o.height <= 0 || !(o.fov > 0 && o.fov < 180) || o.threads < 1 || o.reps < 1) {
        usage();
    }
    return o;
}

/* ---- OBJ: "v x y z" and "f a b c ..." (a corner may be v, v/vt, v//vn, v/vt/vn; negative = relative; fans) ---- */

typedef struct {
    float *pos;      /* x, y, z per vertex */
    size_t nv, cap_v;
    unsigned *tri;   /* 3 per triangle */
    size_t nt, cap_t;
} Mesh;

static void push_vertex(Mesh *m, float x, float y, float z) {
    if (m->nv == m->cap_v) {
        m->cap_v = m->cap_v ? 2 * m->cap_v : 1 << 16;
        m->pos = realloc(m->pos, 3 * m->cap_v * sizeof(float));
        if (!m->pos) die("out of memory", NULL);
    }
    m->pos[3 * m->nv] = x;
    m->pos[3 * m->nv + 1] = y;
    m->pos[3 * m->nv + 2] = z;
    m->nv++;
}

static void push_triangle(Mesh *m, unsigned a, unsigned b, unsigned c) {
    if (m->nt == m->cap_t) {
        m->cap_t = m->cap_t ? 2 * m->cap_t : 1 << 16;
        m->tri = realloc(m->tri, 3 * m->cap_t * sizeof(unsigned));
        if (!m->tri) die("out of memory", NULL);
    }
    m->tri[3 * m->nt] = a;
    m->tri[3 * m->nt + 1] = b;
    m->tri[3 * m->nt + 2] = c;
    m->nt++;
}

static Mesh load_obj(const char *path) {
    Mesh m;
    memset(&m, 0, sizeof m);
    gzFile f = gzopen(path, "rb"); /* reads plain files as they are */
    if (!f) die("cannot open", path);
    gzbuffer(f, 1 << 20);
    char line[4096];
    long lineno = 0;
    while (gzgets(f, line, sizeof line)) {
        lineno++;
        char *s = line;
        while (*s == ' ' || *s == '\t') s++;
        if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t')) {
            char *e;
            float x = strtof(s + 2, &e);
            float y = strtof(e, &e);
            float z = strtof(e, &e);
            push_vertex(&m, x, y, z);
        } else if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t')) {
            long idx[64];
            int n = 0;
            char *p = s + 2;
            for (;;) {
                while (*p == ' ' || *p == '\t') p++;
                if (*p == '\0' || *p == '\n' || *p == '\r' || *p == '#') break;
                char *e;
                long k = strtol(p, &e, 10);
                if (e == p) die("bad face line", line);
                if (k < 0) k = (long) m.nv + k + 1;
                if (k < 1 || (size_t) k > m.nv) {
                    fprintf(stderr, "embree-trace: %s:%ld: vertex index out of range\n", path, lineno);
                    exit(1);
                }
                if (n == 64) die("face with more than 64 corners", NULL);
                idx[n++] = k - 1;
                p = e;
                while (*p && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r') p++; /* skip /vt/vn */
            }
            for (int i = 1; i + 1 < n; i++) {
                push_triangle(&m, (unsigned) idx[0], (unsigned) idx[i], (unsigned) idx[i + 1]);
            }
        }
    }
    gzclose(f);
    if (m.nt == 0) die("no triangles in", path);
    return m;
}

/* ---- the camera: raytracer.cameras.Pinhole and Basis.lookAt ---- */

typedef struct { V3 eye, u, v, w; double half_height, aspect; int hres, vres; } Camera;

static Camera make_camera(const Options *o) {
    Camera c;
    c.eye = o->eye;
    c.w = normalize(sub(o->eye, o->look));
    V3 up = normalize(o->up);
    if (fabs(dot(up, c.w)) > 1 - 1e-9) {
        up = fabs(c.w.z) < 0.9 ? v3(0, 0, 1) : v3(1, 0, 0);
    }
    c.u = normalize(cross(up, c.w));
    c.v = cross(c.w, c.u);
    c.half_height = tan(o->fov * DEGREES_TO_RADIANS / 2);
    c.hres = o->width;
    c.vres = o->height;
    c.aspect = (double) c.hres / c.vres;
    return c;
}

static V3 camera_dir(const Camera *c, double px, double py) {
    double xs = (2 * px / c->hres - 1) * c->half_height * c->aspect;
    double ys = (1 - 2 * py / c->vres) * c->half_height;
    V3 d = v3(xs * c->u.x + ys * c->v.x - c->w.x, xs * c->u.y + ys * c->v.y - c->w.y, xs * c->u.z + ys * c->v.z - c->w.z);
    return scale(d, 1 / sqrt(dot(d, d)));
}

/* ---- per pixel results of the primary pass ---- */

typedef struct {
    float t;
    unsigned geom; /* RTC_INVALID_GEOMETRY_ID on a miss */
    float ng[3];
} Hit;

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *) a, y = *(const double *) b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n) {
    double *s = malloc(n * sizeof(double));
    memcpy(s, v, n * sizeof(double));
    qsort(s, n, sizeof(double), cmp_double);
    double m = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
    free(s);
    return m;
}

static double minimum(const double *v, int n) { double m = v[0]; for (int i = 1; i < n; i++) if (v[i] < m) m = v[i]; return m; }
static double maximum(const double *v, int n) { double m = v[0]; for (int i = 1; i < n; i++) if (v[i] > m) m = v[i]; return m; }

static void error_handler(void *user, enum RTCError code, const char *str) {
    (void) user;
    fprintf(stderr, "embree-trace: Embree error %d: %s\n", (int) code, str ? str : "");
    exit(1);
}

/* The shading frame of a hit: the point (in double, from the double ray) and the unit geometric
 * normal turned towards the viewer, as ShadeRec.complete turns it. */
static void hit_frame(const Camera *cam, const Hit *h, double px, double py, V3 *p, V3 *n) {
    V3 d = camera_dir(cam, px, py);
    *p = add(cam->eye, scale(d, h->t));
    V3 g = normalize(v3(h->ng[0], h->ng[1], h->ng[2]));
    if (dot(g, d) > 0) g = scale(g, -1);
    *n = g;
}

int main(int argc, char **argv) {
    Options o = parse_args(argc, argv);
    omp_set_num_threads(o.threads);

    double t0 = now();
    Mesh mesh = load_obj(o.obj);
    double t_load = now() - t0;

    char config[64];
    snprintf(config, sizeof config, "threads=%d%s", o.threads, o.verbose ? ",verbose=1" : "");
    RTCDevice device = rtcNewDevice(config);
    if (!device) die("rtcNewDevice failed", NULL);
    rtcSetDeviceErrorFunction(device, error_handler, NULL);
    long version = (long) rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION);

    t0 = now();
    RTCScene scene = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *vb = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.nv);
    unsigned *ib = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.nt);
    memcpy(vb, mesh.pos, 3 * mesh.nv * sizeof(float));
    memcpy(ib, mesh.tri, 3 * mesh.nt * sizeof(unsigned));
    rtcCommitGeometry(g);
    unsigned mesh_id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    unsigned plane_id = RTC_INVALID_GEOMETRY_ID;
    V3 plane_n = o.has_plane ? normalize(o.plane_normal) : v3(0, 1, 0);
    if (o.has_plane && !o.plane_apart) {
        /* the plane as a square of side 2 * plane_size around its point, in two triangles */
        V3 n = normalize(o.plane_normal);
        V3 t1 = normalize(fabs(n.x) < 0.9 ? cross(n, v3(1, 0, 0)) : cross(n, v3(0, 1, 0)));
        V3 t2 = cross(n, t1);
        double s = o.plane_size;
        RTCGeometry q = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *qv = rtcSetNewGeometryBuffer(q, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4);
        unsigned *qi = rtcSetNewGeometryBuffer(q, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 2);
        const double corner[4][2] = {{-s, -s}, {s, -s}, {s, s}, {-s, s}};
        for (int k = 0; k < 4; k++) {
            V3 p = add(o.plane_point, add(scale(t1, corner[k][0]), scale(t2, corner[k][1])));
            /* exact on an axis-aligned plane: the coordinate along the normal is the point's */
            if (fabs(n.y) == 1) p.y = o.plane_point.y;
            if (fabs(n.x) == 1) p.x = o.plane_point.x;
            if (fabs(n.z) == 1) p.z = o.plane_point.z;
            qv[3 * k] = (float) p.x;
            qv[3 * k + 1] = (float) p.y;
            qv[3 * k + 2] = (float) p.z;
        }
        const unsigned idx[6] = {0, 1, 2, 0, 2, 3};
        memcpy(qi, idx, sizeof idx);
        rtcCommitGeometry(q);
        plane_id = rtcAttachGeometry(scene, q);
        rtcReleaseGeometry(q);
    }
    rtcCommitScene(scene);
    double t_build = now() - t0;

    Camera cam = make_camera(&o);
    const int W = o.width, H = o.height;
    Hit *hits = malloc((size_t) W * H * sizeof(Hit));
    unsigned char *blocked = calloc((size_t) W * H * MAX_LIGHTS, 1); /* 0 no ray, 1 lit, 2 blocked */
    if (!hits || !blocked) die("out of memory", NULL);

    double *tp = malloc(o.reps * sizeof(double)), *ts = malloc(o.reps * sizeof(double)), *tt = malloc(o.reps * sizeof(double));
    long mesh_hits = 0, plane_hits = 0, misses = 0;
    const float eps = (float) o.shadow_eps;

    /* The rays are made before the timed passes (the trace is Embree's work alone): the primary
     * rays' directions here, the shadow rays from the hits of an untimed first primary pass. */
    double t_setup0 = now();
    float *pdir = malloc((size_t) W * H * 3 * sizeof(float));
    float *ptplane = malloc((size_t) W * H * sizeof(float));
    if (!pdir || !ptplane) die("out of memory", NULL);
#pragma omp parallel for schedule(static)
    for (int y = 0; y < H; y++) {
        for (int x = 0; x < W; x++) {
            size_t i = (size_t) y * W + x;
            V3 d = camera_dir(&cam, x + 0.5, y + 0.5);
            pdir[3 * i] = (float) d.x;
            pdir[3 * i + 1] = (float) d.y;
            pdir[3 * i + 2] = (float) d.z;
            float t_plane = INFINITY;
            if (o.plane_apart) {
                double denom = dot(d, plane_n);
                double t = denom != 0 ? dot(sub(o.plane_point, cam.eye), plane_n) / denom : -1;
                if (t > 0) t_plane = (float) t;
            }
            ptplane[i] = t_plane;
        }
    }
    double t_setup_primary = now() - t_setup0;
    const float ex = (float) cam.eye.x, ey = (float) cam.eye.y, ez = (float) cam.eye.z;

    /* one shadow ray: origin, direction, and which pixel and light it serves */
    typedef struct { float org[3], dir[3]; unsigned pixel; unsigned char light, plane_blocks; } Shadow;
    Shadow *shadows = NULL;
    unsigned char *occluded = NULL;
    long nshadow = 0;
    double t_setup_shadow = 0;

    for (int rep = -1; rep < o.reps; rep++) { /* rep -1: the untimed pass that the shadow rays start from */
        long mh = 0, ph = 0, mi = 0;
        double a = now();
#pragma omp parallel for schedule(dynamic, 2) reduction(+ : mh, ph, mi)
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                size_t i = (size_t) y * W + x;
                struct RTCRayHit rh;
                rh.ray.org_x = ex;
                rh.ray.org_y = ey;
                rh.ray.org_z = ez;
                rh.ray.tnear = 0;
                rh.ray.dir_x = pdir[3 * i];
                rh.ray.dir_y = pdir[3 * i + 1];
                rh.ray.dir_z = pdir[3 * i + 2];
                rh.ray.time = 0;
                rh.ray.tfar = ptplane[i]; /* +inf unless the plane is apart */
                rh.ray.mask = 0xFFFFFFFFu;
                rh.ray.id = 0;
                rh.ray.flags = 0;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
#if EMBREE_MAJOR >= 4
                rtcIntersect1(scene, &rh, NULL);
#else
                struct RTCIntersectContext ctx;
                rtcInitIntersectContext(&ctx);
                rtcIntersect1(scene, &ctx, &rh);
#endif
                Hit *h = &hits[i];
                h->geom = rh.hit.geomID;
                h->t = rh.ray.tfar;
                h->ng[0] = rh.hit.Ng_x;
                h->ng[1] = rh.hit.Ng_y;
                h->ng[2] = rh.hit.Ng_z;
                if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID && ptplane[i] < INFINITY) {
                    h->geom = PLANE_APART_ID;
                    h->t = ptplane[i];
                    h->ng[0] = (float) plane_n.x;
                    h->ng[1] = (float) plane_n.y;
                    h->ng[2] = (float) plane_n.z;
                }
                if (h->geom == mesh_id) mh++;
                else if (h->geom == RTC_INVALID_GEOMETRY_ID) mi++;
                else ph++;
            }
        }
        double b = now();
        if (rep == -1) {
            /* the shadow rays of these hits, in pixel order, made once */
            double s0 = now();
            shadows = malloc((size_t) W * H * o.nlights * sizeof(Shadow));
            occluded = malloc((size_t) W * H * o.nlights);
            if (!shadows || !occluded) die("out of memory", NULL);
            for (size_t i = 0; i < (size_t) W * H; i++) {
                const Hit *h = &hits[i];
                if (h->geom == RTC_INVALID_GEOMETRY_ID) continue;
                V3 p, n;
                hit_frame(&cam, h, i % W + 0.5, i / W + 0.5, &p, &n);
                for (int l = 0; l < o.nlights; l++) {
                    V3 to = sub(o.light[l], p);
                    if (dot(n, to) <= 0) continue; /* the light is behind the surface: no ray, as ours */
                    /* the origin off the surface by eps (relative to the point's size), towards the light */
                    double off = eps * (1 + fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
                    V3 org = add(p, scale(n, off));
                    V3 dir = sub(o.light[l], org);
                    Shadow *sh = &shadows[nshadow++];
                    sh->org[0] = (float) org.x;
                    sh->org[1] = (float) org.y;
                    sh->org[2] = (float) org.z;
                    sh->dir[0] = (float) dir.x;
                    sh->dir[1] = (float) dir.y;
                    sh->dir[2] = (float) dir.z;
                    sh->pixel = (unsigned) i;
                    sh->light = (unsigned char) l;
                    sh->plane_blocks = o.plane_apart && dot(sub(org, o.plane_point), plane_n) * dot(sub(o.light[l], o.plane_point), plane_n) < 0;
                }
            }
            t_setup_shadow = now() - s0;
            continue;
        }
        /* the shadow rays, in chunks of two rows' worth, as the primary rays */
        const long chunk = 2L * W;
#pragma omp parallel for schedule(dynamic, 1)
        for (long c0 = 0; c0 < nshadow; c0 += chunk) {
            long c1 = c0 + chunk < nshadow ? c0 + chunk : nshadow;
            for (long k = c0; k < c1; k++) {
                const Shadow *sh = &shadows[k];
                if (sh->plane_blocks) { /* the plane lies between */
                    occluded[k] = 1;
                    continue;
                }
                struct RTCRay r;
                r.org_x = sh->org[0];
                r.org_y = sh->org[1];
                r.org_z = sh->org[2];
                r.tnear = 0;
                r.dir_x = sh->dir[0];
                r.dir_y = sh->dir[1];
                r.dir_z = sh->dir[2];
                r.time = 0;
                r.tfar = 1.0f - 1e-5f;
                r.mask = 0xFFFFFFFFu;
                r.id = 0;
                r.flags = 0;
#if EMBREE_MAJOR >= 4
                rtcOccluded1(scene, &r, NULL);
#else
                struct RTCIntersectContext ctx;
                rtcInitIntersectContext(&ctx);
                rtcOccluded1(scene, &ctx, &r);
#endif
                occluded[k] = r.tfar == -INFINITY;
            }
        }
        double c = now();
        tp[rep] = b - a;
        ts[rep] = c - b;
        tt[rep] = c - a;
        mesh_hits = mh;
        plane_hits = ph;
        misses = mi;
    }
    long shadow_rays = nshadow, shadow_blocked = 0;
    for (long k = 0; k < nshadow; k++) {
        shadow_blocked += occluded[k];
        blocked[(size_t) shadows[k].pixel * MAX_LIGHTS + shadows[k].light] = occluded[k] ? 2 : 1;
    }

    long rays = (long) W * H;
    printf("embree %ld.%ld.%ld (Embree %d API), %d threads, %d repetitions\n", version / 10000, version / 100 % 100, version % 100,
           EMBREE_MAJOR, o.threads, o.reps);
    printf("mesh %s: %zu triangles, %zu vertices; load %.3f s, build %.3f s; rays made before the timed passes "
           "(untimed): primary %.3f s, shadow %.3f s (one thread)\n", o.obj, mesh.nt, mesh.nv, t_load, t_build, t_setup_primary, t_setup_shadow);
    printf("plane: %s\n", !o.has_plane ? "none" : o.plane_apart ? "apart (computed per ray; it clips the primary rays' tfar)" : "in Embree's scene (two triangles)");
    printf("rays: primary %ld (mesh %ld, plane %ld, miss %ld), shadow %ld, blocked %ld (%.2f%%)\n", rays, mesh_hits, plane_hits,
           misses, shadow_rays, shadow_blocked, 100.0 * shadow_blocked / (shadow_rays ? shadow_rays : 1));
    printf("trace median (min-max) over %d: primary %.4f s (%.4f-%.4f), shadow %.4f s (%.4f-%.4f), total %.4f s (%.4f-%.4f), %.1f M rays/s\n",
           o.reps, median(tp, o.reps), minimum(tp, o.reps), maximum(tp, o.reps), median(ts, o.reps), minimum(ts, o.reps),
           maximum(ts, o.reps), median(tt, o.reps), minimum(tt, o.reps), maximum(tt, o.reps),
           (rays + shadow_rays) / median(tt, o.reps) / 1e6);
    printf("RESULT plane=%s embree=%ld.%ld.%ld threads=%d reps=%d load_s=%.4f build_s=%.4f primary_s=%.4f shadow_s=%.4f total_s=%.4f "
           "primary=%ld mesh_hits=%ld plane_hits=%ld misses=%ld shadow=%ld blocked=%ld\n",
           !o.has_plane ? "none" : o.plane_apart ? "apart" : "bvh", version / 10000, version / 100 % 100, version % 100, o.threads, o.reps, t_load, t_build, median(tp, o.reps),
           median(ts, o.reps), median(tt, o.reps), rays, mesh_hits, plane_hits, misses, shadow_rays, shadow_blocked);

    if (o.pfm) {
        /* shade as the ray-cast tracer does for matte materials and point lights (untimed) */
        FILE *f = fopen(o.pfm, "wb");
        if (!f) die("cannot write", o.pfm);
        fprintf(f, "PF\n%d %d\n-1.0\n", W, H);
        float *row = malloc(3 * W * sizeof(float));
        for (int y = H - 1; y >= 0; y--) {
            for (int x = 0; x < W; x++) {
                size_t i = (size_t) y * W + x;
                const Hit *h = &hits[i];
                V3 L = o.background;
                if (h->geom != RTC_INVALID_GEOMETRY_ID) {
                    int on_mesh = h->geom == mesh_id;
                    double ka = on_mesh ? o.mesh_ka : o.plane_ka, kd = on_mesh ? o.mesh_kd : o.plane_kd;
                    V3 cd = on_mesh ? o.mesh_color : o.plane_color;
                    V3 p, n;
                    hit_frame(&cam, h, x + 0.5, y + 0.5, &p, &n);
                    L = scale(cd, ka * o.ambient);
                    for (int l = 0; l < o.nlights; l++) {
                        if (blocked[i * MAX_LIGHTS + l] != 1) continue;
                        V3 to = sub(o.light[l], p);
                        double r2 = dot(to, to);
                        double cosine = dot(n, to) / sqrt(r2);
                        double k = kd / PI * o.light_ls[l] / r2 * cosine;
                        L = add(L, v3(cd.x * o.light_color[l].x * k, cd.y * o.light_color[l].y * k, cd.z * o.light_color[l].z * k));
                    }
                }
                row[3 * x] = (float) L.x;
                row[3 * x + 1] = (float) L.y;
                row[3 * x + 2] = (float) L.z;
            }
            fwrite(row, sizeof(float), 3 * W, f);
        }
        free(row);
        fclose(f);
        (void) plane_id;
    }
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}
