#pragma once
// The plugin interface of LAMMPS' PLUGIN package as its documentation describes it ("Writing
// plugins": the record a plugin hands to the loader, and the three-argument entry point), declared
// here so that the test can build the package's plugin against Debian's LAMMPS, which ships no
// lammpsplugin.h, and load it as LAMMPS' `plugin load` would. Only the test uses this file; a
// plugin for a real LAMMPS is built against that LAMMPS' own header.
#ifdef __cplusplus
extern "C" {
#endif

typedef void*(lammpsplugin_factory1)(void* lmp);
typedef void*(lammpsplugin_factory2)(void* lmp, int narg, char** arg);

typedef struct {
  const char* version;
  const char* style;
  const char* name;
  const char* info;
  const char* author;
  union {
    lammpsplugin_factory1* v1;
    lammpsplugin_factory2* v2;
  } creator;
  void* handle;
} lammpsplugin_t;

typedef void (*lammpsplugin_regfunc)(lammpsplugin_t* plugin, void* lmp);

void lammpsplugin_init(void* lmp, void* handle, void* regfunc);

#ifdef __cplusplus
}
#endif
