// Times each step of opening a Vulkan device, the way wgpu's Vulkan backend does it.
#include <dlfcn.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
typedef int32_t VkResult;
typedef void *VkInstance, *VkPhysicalDevice, *VkDevice;
typedef void (*PFN)(void);
typedef PFN (*PFN_gipa)(VkInstance, const char *);
typedef struct { int sType; const void *pNext; const char *app; uint32_t appVer; const char *eng; uint32_t engVer; uint32_t api; } AppInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; const AppInfo *app; uint32_t nl; const char *const *l; uint32_t ne; const char *const *e; } InstInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; uint32_t family; uint32_t count; const float *prio; } QueueInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; uint32_t nq; const QueueInfo *q; uint32_t nl; const char *const *l; uint32_t ne; const char *const *e; const void *features; } DevInfo;
static double t0;
static double now(void) { struct timespec ts; clock_gettime(CLOCK_MONOTONIC, &ts); return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6; }
static double last;
static void mark(const char *what) { double t = now(); printf("vkopen %8.2f ms (+%7.2f) %s\n", t - t0, t - last, what); last = t; fflush(stdout); }
int main(int argc, char **argv) {
  t0 = last = now();
  int rounds = argc > 1 ? atoi(argv[1]) : 2;
  void *lib = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
  if (!lib) { printf("no loader: %s\n", dlerror()); return 1; }
  mark("dlopen libvulkan.so.1");
  PFN_gipa gipa = (PFN_gipa)dlsym(lib, "vkGetInstanceProcAddr");
  VkResult (*enumExt)(const char *, uint32_t *, void *) = (void *)gipa(NULL, "vkEnumerateInstanceExtensionProperties");
  VkResult (*enumLay)(uint32_t *, void *) = (void *)gipa(NULL, "vkEnumerateInstanceLayerProperties");
  VkResult (*createInst)(const InstInfo *, const void *, VkInstance *) = (void *)gipa(NULL, "vkCreateInstance");
  for (int round = 0; round < rounds; round++) {
    printf("vkopen round %d\n", round);
    last = now();
    uint32_t n = 0; enumExt(NULL, &n, NULL); char *props = malloc(260 * (n + 1)); enumExt(NULL, &n, props);
    mark("vkEnumerateInstanceExtensionProperties");
    uint32_t nl = 0; enumLay(&nl, NULL);
    printf("  %u instance extensions, %u layers\n", n, nl);
    mark("vkEnumerateInstanceLayerProperties");
    AppInfo app = {0, NULL, "vkopen", 1, "vkopen", 1, (1u << 22) | (3u << 12)};
    InstInfo ii = {1, NULL, 0, &app, 0, NULL, 0, NULL};
    VkInstance inst; VkResult r = createInst(&ii, NULL, &inst);
    mark("vkCreateInstance"); if (r) { printf("vkCreateInstance %d\n", r); return 1; }
    VkResult (*enumPD)(VkInstance, uint32_t *, VkPhysicalDevice *) = (void *)gipa(inst, "vkEnumeratePhysicalDevices");
    void (*props_)(VkPhysicalDevice, void *) = (void *)gipa(inst, "vkGetPhysicalDeviceProperties");
    void (*qfp)(VkPhysicalDevice, uint32_t *, void *) = (void *)gipa(inst, "vkGetPhysicalDeviceQueueFamilyProperties");
    void (*fmt)(VkPhysicalDevice, int, void *) = (void *)gipa(inst, "vkGetPhysicalDeviceFormatProperties");
    VkResult (*createDev)(VkPhysicalDevice, const DevInfo *, const void *, VkDevice *) = (void *)gipa(inst, "vkCreateDevice");
    PFN_gipa gdpa = (PFN_gipa)gipa(inst, "vkGetDeviceProcAddr");
    void (*destroyInst)(VkInstance, const void *) = (void *)gipa(inst, "vkDestroyInstance");
    uint32_t np = 0; enumPD(inst, &np, NULL); VkPhysicalDevice pd[16]; if (np > 16) np = 16; enumPD(inst, &np, pd);
    mark("vkEnumeratePhysicalDevices");
    static char p[8192]; props_(pd[0], p); printf("  %u devices; first: %s (type %d)\n", np, p + 20, *(int *)(p + 16));
    uint32_t nq = 0; qfp(pd[0], &nq, NULL);
    static char fp[64]; for (int f = 0; f < 185; f++) fmt(pd[0], f, fp);
    mark("properties, queue families, 185 format properties");
    float prio = 1.0f; QueueInfo qi = {2, NULL, 0, 0, 1, &prio};
    DevInfo di = {3, NULL, 0, 1, &qi, 0, NULL, 0, NULL, NULL};
    VkDevice dev; r = createDev(pd[0], &di, NULL, &dev);
    mark("vkCreateDevice (one queue, no extensions)"); if (r) { printf("vkCreateDevice %d\n", r); return 1; }
    void (*destroyDev)(VkDevice, const void *) = (void *)gdpa(dev, "vkDestroyDevice");
    destroyDev(dev, NULL);
    mark("vkDestroyDevice");
    destroyInst(inst, NULL);
    mark("vkDestroyInstance");
  }
  return 0;
}
