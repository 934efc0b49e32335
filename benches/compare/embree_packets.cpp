// Embree 3 on rays written by `examples/render_rays.rs`: one ray a query
// (rtcIntersect1) against packets of 8 and 16 (rtcIntersect8/16), one
// thread, as Mitsuba 3's LLVM variants trace with their own Embree 3
// (packets as wide as the vector unit; camera rays with the coherent
// context flag). Built by `benches/compare/packets.sh`.
//
//   embree_packets DIR ROBUST COHERENT
//
// ROBUST 1 sets RTC_SCENE_FLAG_ROBUST (watertight, as this project's
// test); COHERENT 1 sets RTC_INTERSECT_CONTEXT_FLAG_COHERENT, 0 the
// incoherent flag. Prints, per ray set and query width, the rays, hits,
// the sum of hit distances (to check against the other widths) and the
// median rate of five passes.
#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#ifdef EMBREE_IN_MITSUBA_NAMESPACE
using namespace mitsuba;
#endif

static std::vector<float> load(const std::string &path) {
    FILE *file = std::fopen(path.c_str(), "rb");
    if (!file) {
        std::fprintf(stderr, "%s: cannot open\n", path.c_str());
        std::exit(1);
    }
    std::fseek(file, 0, SEEK_END);
    long bytes = std::ftell(file);
    std::fseek(file, 0, SEEK_SET);
    std::vector<float> data(bytes / 4);
    if (std::fread(data.data(), 4, data.size(), file) != data.size()) std::exit(1);
    std::fclose(file);
    return data;
}

// Fills lane k of a packet (RTCRayHit8 or RTCRayHit16) from ray q.
template <typename Packet> static void fill(Packet &p, int k, const float *q) {
    p.ray.org_x[k] = q[0]; p.ray.org_y[k] = q[1]; p.ray.org_z[k] = q[2];
    p.ray.dir_x[k] = q[3]; p.ray.dir_y[k] = q[4]; p.ray.dir_z[k] = q[5];
    p.ray.tnear[k] = q[6]; p.ray.tfar[k] = q[7]; p.ray.time[k] = 0;
    p.ray.mask[k] = ~0u; p.ray.id[k] = 0; p.ray.flags[k] = 0;
    p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    p.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

struct Tally { long hits = 0; double distances = 0; };

template <int W, typename Packet, typename Query>
static void trace_packets(const std::vector<float> &rays, Query query, Tally &tally) {
    alignas(64) Packet packet;
    alignas(64) int valid[W];
    std::fill(valid, valid + W, -1);
    size_t n = rays.size() / 8;
    for (size_t i = 0; i + W <= n; i += W) {
        for (int k = 0; k < W; k++) fill(packet, k, &rays[8 * (i + k)]);
        query(valid, &packet);
        for (int k = 0; k < W; k++)
            if (packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID) {
                tally.hits++;
                tally.distances += packet.ray.tfar[k];
            }
    }
}

int main(int argc, char **argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: embree_packets DIR ROBUST COHERENT\n");
        return 1;
    }
    std::string dir = argv[1];
    bool robust = std::atoi(argv[2]) != 0, coherent = std::atoi(argv[3]) != 0;
    std::vector<float> corners = load(dir + "/triangles.bin");
    size_t triangles = corners.size() / 9;
    RTCDevice device = rtcNewDevice("threads=1");
    RTCScene scene = rtcNewScene(device);
    if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto *vertices = (float *)rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0,
                                                      RTC_FORMAT_FLOAT3, 12, 3 * triangles);
    auto *indices = (unsigned *)rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0,
                                                        RTC_FORMAT_UINT3, 12, triangles);
    std::copy(corners.begin(), corners.end(), vertices);
    for (unsigned i = 0; i < 3 * triangles; i++) indices[i] = i;
    rtcCommitGeometry(mesh);
    rtcAttachGeometry(scene, mesh);
    rtcReleaseGeometry(mesh);
    rtcCommitScene(scene);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    for (const char *set : {"camera", "bounce"}) {
        std::vector<float> rays = load(dir + "/" + set + ".bin");
        size_t n = rays.size() / 8;
        for (int width : {1, 8, 16}) {
            std::vector<double> rates;
            Tally tally;
            for (int pass = 0; pass < 5; pass++) {
                tally = Tally();
                auto start = std::chrono::steady_clock::now();
                if (width == 1) {
                    for (size_t i = 0; i < n; i++) {
                        RTCRayHit one;
                        const float *q = &rays[8 * i];
                        one.ray.org_x = q[0]; one.ray.org_y = q[1]; one.ray.org_z = q[2];
                        one.ray.dir_x = q[3]; one.ray.dir_y = q[4]; one.ray.dir_z = q[5];
                        one.ray.tnear = q[6]; one.ray.tfar = q[7]; one.ray.time = 0;
                        one.ray.mask = ~0u; one.ray.id = 0; one.ray.flags = 0;
                        one.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                        one.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                        rtcIntersect1(scene, &context, &one);
                        if (one.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
                            tally.hits++;
                            tally.distances += one.ray.tfar;
                        }
                    }
                } else if (width == 8) {
                    trace_packets<8, RTCRayHit8>(rays, [&](const int *v, RTCRayHit8 *p) {
                        rtcIntersect8(v, scene, &context, p); }, tally);
                } else {
                    trace_packets<16, RTCRayHit16>(rays, [&](const int *v, RTCRayHit16 *p) {
                        rtcIntersect16(v, scene, &context, p); }, tally);
                }
                std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
                rates.push_back(n / seconds.count() / 1e6);
            }
            std::sort(rates.begin(), rates.end());
            std::printf("Embree %s, %s flag, %s rays, %2d a query: %zu rays, %ld hits, sum of t %.1f, %.2f Mrays/s\n",
                        robust ? "robust" : "default", coherent ? "coherent" : "incoherent", set, width, n,
                        tally.hits, tally.distances, rates[2]);
        }
    }
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}
