// How long a process with an open Vulkan device takes to end, by way of ending:
//   vkexit MODE [MB]   MODE: exit | _exit | destroy | fork
// It opens a device, allocates MB of host-cached memory (read-back buffers) and MB of
// device-local host-visible memory (staging), maps both, then prints the wall clock (ms)
// and ends by MODE. The caller subtracts that from the time it sees the process end.
// Also: `vkexit par N` allocates 133 MB of host-cached memory as N pieces on N threads.
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
typedef int32_t VkResult;
typedef void *VkInstance, *VkPhysicalDevice, *VkDevice;
typedef uint64_t VkDeviceMemory;
typedef void (*PFN)(void);
typedef PFN (*PFN_gipa)(VkInstance, const char *);
typedef struct { int sType; const void *pNext; const char *app; uint32_t appVer; const char *eng; uint32_t engVer; uint32_t api; } AppInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; const AppInfo *app; uint32_t nl; const char *const *l; uint32_t ne; const char *const *e; } InstInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; uint32_t family; uint32_t count; const float *prio; } QueueInfo;
typedef struct { int sType; const void *pNext; uint32_t flags; uint32_t nq; const QueueInfo *q; uint32_t nl; const char *const *l; uint32_t ne; const char *const *e; const void *features; } DevInfo;
typedef struct { uint32_t flags, heap; } MemType;
typedef struct { uint64_t size; uint32_t flags; } MemHeap;
typedef struct { uint32_t ntypes; MemType types[32]; uint32_t nheaps; MemHeap heaps[16]; } MemProps;
typedef struct { int sType; const void *pNext; uint64_t size; uint32_t type; } AllocInfo;
static double wall(void) { struct timespec ts; clock_gettime(CLOCK_REALTIME, &ts); return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6; }
static VkResult (*alloc)(VkDevice, const AllocInfo *, const void *, VkDeviceMemory *);
static VkResult (*map)(VkDevice, VkDeviceMemory, uint64_t, uint64_t, uint32_t, void **);
static VkDevice dev;
typedef struct { uint64_t size; uint32_t type; VkDeviceMemory m; } Piece;
static void *one(void *a) { Piece *p = a; AllocInfo ai = {5, NULL, p->size, p->type}; alloc(dev, &ai, NULL, &p->m); return NULL; }
static int find(MemProps *mp, uint32_t want) { for (uint32_t t = 0; t < mp->ntypes; t++) if ((mp->types[t].flags & want) == want) return t; return -1; }
int main(int argc, char **argv) {
  const char *mode = argc > 1 ? argv[1] : "exit";
  uint64_t mb = argc > 2 ? atoll(argv[2]) : 133;
  void *lib = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
  PFN_gipa gipa = (PFN_gipa)dlsym(lib, "vkGetInstanceProcAddr");
  VkResult (*createInst)(const InstInfo *, const void *, VkInstance *) = (void *)gipa(NULL, "vkCreateInstance");
  AppInfo app = {0, NULL, "vkexit", 1, "vkexit", 1, (1u << 22) | (3u << 12)};
  InstInfo ii = {1, NULL, 0, &app, 0, NULL, 0, NULL};
  VkInstance inst; if (createInst(&ii, NULL, &inst)) return 1;
  VkResult (*enumPD)(VkInstance, uint32_t *, VkPhysicalDevice *) = (void *)gipa(inst, "vkEnumeratePhysicalDevices");
  void (*memprops)(VkPhysicalDevice, MemProps *) = (void *)gipa(inst, "vkGetPhysicalDeviceMemoryProperties");
  VkResult (*createDev)(VkPhysicalDevice, const DevInfo *, const void *, VkDevice *) = (void *)gipa(inst, "vkCreateDevice");
  void (*destroyInst)(VkInstance, const void *) = (void *)gipa(inst, "vkDestroyInstance");
  PFN_gipa gdpa = (PFN_gipa)gipa(inst, "vkGetDeviceProcAddr");
  uint32_t np = 1; VkPhysicalDevice pd; enumPD(inst, &np, &pd);
  MemProps mp; memprops(pd, &mp);
  float prio = 1.0f; QueueInfo qi = {2, NULL, 0, 0, 1, &prio};
  DevInfo di = {3, NULL, 0, 1, &qi, 0, NULL, 0, NULL, NULL};
  if (createDev(pd, &di, NULL, &dev)) return 1;
  alloc = (void *)gdpa(dev, "vkAllocateMemory");
  map = (void *)gdpa(dev, "vkMapMemory");
  void (*freem)(VkDevice, VkDeviceMemory, const void *) = (void *)gdpa(dev, "vkFreeMemory");
  void (*destroyDev)(VkDevice, const void *) = (void *)gdpa(dev, "vkDestroyDevice");
  int cached = find(&mp, 0xa), bar = find(&mp, 0x7);
  if (!strcmp(mode, "par")) {
    int n = (int)mb; Piece p[64]; pthread_t t[64]; uint64_t size = 132710400;
    for (int rep = 0; rep < 2; rep++) {
      double a = wall();
      for (int i = 0; i < n; i++) { p[i] = (Piece){size / n, cached, 0}; pthread_create(&t[i], NULL, one, &p[i]); }
      for (int i = 0; i < n; i++) pthread_join(t[i], NULL);
      double b = wall();
      for (int i = 0; i < n; i++) freem(dev, p[i].m, NULL);
      printf("vkexit par: 133 MB host-cached as %d pieces on %d threads: %.2f ms (freed in %.2f)\n", n, n, b - a, wall() - b);
    }
    return 0;
  }
  VkDeviceMemory m1, m2; void *p1, *p2;
  AllocInfo a1 = {5, NULL, mb << 20, cached}, a2 = {5, NULL, mb << 20, bar};
  if (mb) { alloc(dev, &a1, NULL, &m1); map(dev, m1, 0, mb << 20, 0, &p1); alloc(dev, &a2, NULL, &m2); map(dev, m2, 0, mb << 20, 0, &p2); memset(p2, 1, mb << 20); }
  fflush(stdout);
  if (!strcmp(mode, "destroy")) { double a = wall(); if (mb) { freem(dev, m1, NULL); freem(dev, m2, NULL); } double b = wall(); destroyDev(dev, NULL); double c = wall(); destroyInst(inst, NULL); fprintf(stderr, "destroy: memory %.2f ms, device %.2f, instance %.2f\n", b - a, c - b, wall() - c); }
  printf("%.3f\n", wall()); fflush(stdout);
  if (!strcmp(mode, "_exit")) _exit(0);
  if (!strcmp(mode, "fork")) {
    int fds[2]; if (pipe(fds)) return 1;
    if (fork() == 0) {  // holds the device's files until the parent has gone, then ends
      close(fds[1]); close(0); close(1); close(2); char c; while (read(fds[0], &c, 1) > 0) {} _exit(0);
    }
    _exit(0);
  }
  exit(0);
}
