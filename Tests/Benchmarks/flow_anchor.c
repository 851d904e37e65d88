/* Anchor for the flow benchmark: Embree 3 (Debian's libembree-dev), the ray caster inside Open3D's RaycastingScene,
 * casting the same primary rays on the same mesh with rtcIntersect1 on one thread; CPU time, the cheapest of N rounds.
 * (Debian's python3-open3d 0.16 returned no hit for any ray here, even on a unit box, so Embree is called directly.)
 * Usage: flow_anchor DUMP_DIR ROUNDS. Prints "key TAB value" lines. Built by run-all with cc -O2 -lembree3. */
#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static void *slurp(const char *dir, const char *name, long *bytes)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) { perror(path); exit(1); }
    fseek(f, 0, SEEK_END);
    *bytes = ftell(f);
    fseek(f, 0, SEEK_SET);
    void *data = malloc(*bytes);
    if (fread(data, 1, *bytes, f) != (size_t)*bytes) { perror(path); exit(1); }
    fclose(f);
    return data;
}

static double cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

int main(int argc, char **argv)
{
    if (argc < 3) { fprintf(stderr, "usage: flow_anchor DUMP_DIR ROUNDS\n"); return 2; }
    int rounds = atoi(argv[2]);
    long vb, tb, rb;
    double *v = slurp(argv[1], "vertices.f64", &vb);
    unsigned *t = slurp(argv[1], "triangles.i32", &tb);
    float *r = slurp(argv[1], "rays.f32", &rb);
    long nv = vb / 24, nt = tb / 12, nr = rb / 24;
    /* One build thread too, so that build time compares with the single-thread C# build. */
    RTCDevice device = rtcNewDevice("threads=1");
    double build = INFINITY, cast = INFINITY;
    long hits = 0;
    for (int round = 0; round < rounds; round++) {
        double t0 = cpu_ms();
        RTCScene scene = rtcNewScene(device);
        RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *vertices = rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv);
        for (long i = 0; i < 3 * nv; i++) vertices[i] = (float)v[i];
        unsigned *indices = rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt);
        for (long i = 0; i < 3 * nt; i++) indices[i] = t[i];
        rtcCommitGeometry(mesh);
        rtcAttachGeometry(scene, mesh);
        rtcReleaseGeometry(mesh);
        rtcCommitScene(scene);
        double t1 = cpu_ms();
        struct RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        hits = 0;
        for (long i = 0; i < nr; i++) {
            struct RTCRayHit h;
            const float *q = r + 6 * i;
            h.ray.org_x = q[0]; h.ray.org_y = q[1]; h.ray.org_z = q[2];
            h.ray.dir_x = q[3]; h.ray.dir_y = q[4]; h.ray.dir_z = q[5];
            h.ray.tnear = 0; h.ray.tfar = INFINITY; h.ray.mask = 0xFFFFFFFF; h.ray.flags = 0; h.ray.time = 0;
            h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &context, &h);
            if (h.hit.geomID != RTC_INVALID_GEOMETRY_ID) hits++;
        }
        double t2 = cpu_ms();
        rtcReleaseScene(scene);
        if (t1 - t0 < build) build = t1 - t0;
        if (t2 - t1 < cast) cast = t2 - t1;
    }
    printf("flow.embree.build.ms\t%f\nflow.embree.primary.ms\t%f\nflow.embree.cast.ns\t%f\nflow.embree.hits\t%ld\n", build, cast, cast * 1e6 / nr, hits);
    rtcReleaseDevice(device);
    return 0;
}
