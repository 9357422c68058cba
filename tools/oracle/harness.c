/* Microsoft's shader compiler over a list of files, in one process.
 *
 *   harness.exe MODE LIST OUTDIR          MODE: asm | hlsl | dis
 *
 * Built with MinGW and run under Wine beside d3dcompiler_47.dll (tools/oracle/setup.sh).
 * LIST holds one absolute Windows path a line (LF or CRLF); a line may add a TAB and the
 * output folder for that input (instead of OUTDIR), and another TAB and the name the compiler
 * is told the file has (its file name otherwise). For an input whose file name is NAME:
 *
 *   NAME.rc       the HRESULT in eight hex digits and a LF (00000000: accepted)
 *   NAME.err      Microsoft's messages, when it wrote any (errors and warnings)
 *   NAME.fxo      the bytecode, when there is some
 *   NAME.dis      D3DDisassemble's listing of that bytecode, the blob as returned
 *   NAME.dis.rc   D3DAssemble of that listing: the HRESULT
 *   NAME.dis.fxo  ... and its bytecode
 *
 * asm assembles the file with D3DAssemble; hlsl compiles it with D3DCompile (target ps_3_0,
 * entry main, no flags, unless the first line reads `// oracle: key=value ...` with keys
 * flags=NAME|NAME (D3DCOMPILE_* names, prefix optional), entry=NAME, target=NAME); dis takes
 * the file as bytecode. Microsoft's messages name a file by its full path, the name it was
 * given resolved against the current folder: the harness works in C:\ (the Wine prefix's own
 * drive), so the messages read C:\NAME(line,col) wherever the corpus lives. The round trip
 * names its listing NAME.dis. The blob D3DDisassemble returns ends with a NUL (kept in
 * NAME.dis); D3DAssemble reads text up to a NUL, so the round trip gives it the text before.
 *
 * Exit status: 0 when every input was read and every answer written; 1 when some input could
 * not be read, a first line asked for something unknown or an output could not be written
 * (each said on stderr, the other inputs still done); 2 usage; 3 Microsoft's DLL is not beside
 * the harness, does not load, or lacks an export (Wine's own builtin DLL is never used).
 * The last line on stderr is `harness: N of M inputs answered`. */
#include <windows.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <d3dcommon.h>
#include <d3dcompiler.h>

typedef HRESULT(WINAPI *assemble_fn)(const void *, SIZE_T, const char *, const D3D_SHADER_MACRO *,
                                     ID3DInclude *, UINT, ID3DBlob **, ID3DBlob **);
typedef HRESULT(WINAPI *disassemble_fn)(const void *, SIZE_T, UINT, const char *, ID3DBlob **);
typedef HRESULT(WINAPI *compile_fn)(const void *, SIZE_T, const char *, const D3D_SHADER_MACRO *,
                                    ID3DInclude *, const char *, const char *, UINT, UINT,
                                    ID3DBlob **, ID3DBlob **);

static assemble_fn assemble;
static disassemble_fn disassemble;
static compile_fn compile;
static int failures;

struct flag {
    const char *name;
    UINT value;
};

static const struct flag FLAGS[] = {
    {"DEBUG", D3DCOMPILE_DEBUG},
    {"SKIP_VALIDATION", D3DCOMPILE_SKIP_VALIDATION},
    {"SKIP_OPTIMIZATION", D3DCOMPILE_SKIP_OPTIMIZATION},
    {"PACK_MATRIX_ROW_MAJOR", D3DCOMPILE_PACK_MATRIX_ROW_MAJOR},
    {"PACK_MATRIX_COLUMN_MAJOR", D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR},
    {"PARTIAL_PRECISION", D3DCOMPILE_PARTIAL_PRECISION},
    {"FORCE_VS_SOFTWARE_NO_OPT", D3DCOMPILE_FORCE_VS_SOFTWARE_NO_OPT},
    {"FORCE_PS_SOFTWARE_NO_OPT", D3DCOMPILE_FORCE_PS_SOFTWARE_NO_OPT},
    {"NO_PRESHADER", D3DCOMPILE_NO_PRESHADER},
    {"AVOID_FLOW_CONTROL", D3DCOMPILE_AVOID_FLOW_CONTROL},
    {"PREFER_FLOW_CONTROL", D3DCOMPILE_PREFER_FLOW_CONTROL},
    {"ENABLE_STRICTNESS", D3DCOMPILE_ENABLE_STRICTNESS},
    {"ENABLE_BACKWARDS_COMPATIBILITY", D3DCOMPILE_ENABLE_BACKWARDS_COMPATIBILITY},
    {"IEEE_STRICTNESS", D3DCOMPILE_IEEE_STRICTNESS},
    {"OPTIMIZATION_LEVEL0", D3DCOMPILE_OPTIMIZATION_LEVEL0},
    {"OPTIMIZATION_LEVEL1", D3DCOMPILE_OPTIMIZATION_LEVEL1},
    {"OPTIMIZATION_LEVEL2", D3DCOMPILE_OPTIMIZATION_LEVEL2},
    {"OPTIMIZATION_LEVEL3", D3DCOMPILE_OPTIMIZATION_LEVEL3},
    {"WARNINGS_ARE_ERRORS", D3DCOMPILE_WARNINGS_ARE_ERRORS},
};

/* The whole file, with a NUL after it (not counted in *len); NULL if it cannot be read. */
static char *read_all(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, n = 0, got;
    char *buf = malloc(cap + 1);
    while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) {
            cap *= 2;
            char *bigger = realloc(buf, cap + 1);
            if (!bigger) free(buf);
            buf = bigger;
        }
    }
    int bad = ferror(f);
    fclose(f);
    if (!buf || bad) {
        free(buf);
        return NULL;
    }
    buf[n] = 0;
    *len = n;
    return buf;
}

static void write_bytes(const char *dir, const char *name, const char *ext, const void *data,
                        size_t len) {
    char path[4096];
    snprintf(path, sizeof path, "%s\\%s.%s", dir, name, ext);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, len, f) != len || fclose(f) != 0) {
        fprintf(stderr, "harness: cannot write %s\n", path);
        failures++;
    }
}

static void write_blob(const char *dir, const char *name, const char *ext, ID3DBlob *blob) {
    if (blob)
        write_bytes(dir, name, ext, blob->lpVtbl->GetBufferPointer(blob),
                    blob->lpVtbl->GetBufferSize(blob));
}

static void write_rc(const char *dir, const char *name, const char *ext, HRESULT hr) {
    char text[16];
    snprintf(text, sizeof text, "%08lx\n", (unsigned long)(DWORD)hr);
    write_bytes(dir, name, ext, text, 9);
}

static void release(ID3DBlob *blob) {
    if (blob) blob->lpVtbl->Release(blob);
}

/* The value of a `flags=` list (NAME|NAME...), or -1 after saying which name is unknown. */
static long parse_flags(const char *file, const char *list, size_t len) {
    long value = 0;
    while (len > 0) {
        size_t word = 0;
        while (word < len && list[word] != '|') word++;
        const char *name = list;
        size_t n = word;
        if (n > 11 && !strncmp(name, "D3DCOMPILE_", 11)) name += 11, n -= 11;
        size_t i;
        for (i = 0; i < sizeof FLAGS / sizeof FLAGS[0]; i++)
            if (strlen(FLAGS[i].name) == n && !strncmp(FLAGS[i].name, name, n)) break;
        if (i == sizeof FLAGS / sizeof FLAGS[0]) {
            fprintf(stderr, "harness: %s: unknown flag '%.*s' on the `// oracle:` line\n", file,
                    (int)word, list);
            return -1;
        }
        value |= FLAGS[i].value;
        list += word;
        len -= word;
        if (len > 0) list++, len--;
    }
    return value;
}

struct options {
    UINT flags;
    char entry[128];
    char target[32];
};

/* Reads the `// oracle: key=value ...` first line of an HLSL file, if it has one. */
static int hlsl_options(const char *file, const char *src, struct options *o) {
    o->flags = 0;
    strcpy(o->entry, "main");
    strcpy(o->target, "ps_3_0");
    const char *tag = "// oracle:";
    if (strncmp(src, tag, strlen(tag))) return 1;
    const char *p = src + strlen(tag);
    const char *end = p + strcspn(p, "\r\n");
    while (p < end) {
        while (p < end && (*p == ' ' || *p == '\t')) p++;
        const char *word = p;
        while (p < end && *p != ' ' && *p != '\t') p++;
        size_t n = p - word;
        const char *eq = memchr(word, '=', n);
        if (n == 0) break;
        size_t key = eq ? (size_t)(eq - word) : n, vlen = eq ? n - key - 1 : 0;
        if (eq && key == 5 && !strncmp(word, "flags", 5)) {
            long f = parse_flags(file, eq + 1, vlen);
            if (f < 0) return 0;
            o->flags |= (UINT)f;
        } else if (eq && key == 5 && !strncmp(word, "entry", 5) && vlen && vlen < sizeof o->entry) {
            memcpy(o->entry, eq + 1, vlen);
            o->entry[vlen] = 0;
        } else if (eq && key == 6 && !strncmp(word, "target", 6) && vlen &&
                   vlen < sizeof o->target) {
            memcpy(o->target, eq + 1, vlen);
            o->target[vlen] = 0;
        } else {
            fprintf(stderr, "harness: %s: `// oracle:` line: '%.*s' is not flags=, entry= or target=\n",
                    file, (int)n, word);
            return 0;
        }
    }
    return 1;
}

/* The listing of some bytecode, and the round trip: D3DAssemble of that listing. */
static void listing_and_round_trip(const char *dir, const char *name, const char *called,
                                   const void *code, size_t len) {
    ID3DBlob *dis = NULL, *back = NULL, *err = NULL;
    if (FAILED(disassemble(code, len, 0, NULL, &dis)) || !dis) {
        release(dis);
        return;
    }
    write_blob(dir, name, "dis", dis);
    const char *text = dis->lpVtbl->GetBufferPointer(dis);
    size_t n = dis->lpVtbl->GetBufferSize(dis);
    /* The blob ends with a NUL; the listing is the text before it. */
    while (n > 0 && text[n - 1] == 0) n--;
    char dis_name[2048];
    snprintf(dis_name, sizeof dis_name, "%s.dis", called);
    HRESULT hr = assemble(text, n, dis_name, NULL, NULL, 0, &back, &err);
    write_rc(dir, name, "dis.rc", hr);
    write_blob(dir, name, "dis.fxo", back);
    release(dis);
    release(back);
    release(err);
}

/* Answers one input; 0 when it could not be read or asked for something unknown. */
static int answer(const char *mode, const char *path, const char *dir, const char *given) {
    size_t len;
    char *src = read_all(path, &len);
    if (!src) {
        fprintf(stderr, "harness: cannot read %s\n", path);
        return 0;
    }
    const char *name = path;
    for (const char *p = path; *p; p++)
        if (*p == '\\' || *p == '/') name = p + 1;
    const char *called = given ? given : name;
    ID3DBlob *code = NULL, *err = NULL;
    HRESULT hr = S_OK;
    const void *bytecode = NULL;
    size_t bytecode_len = 0;
    if (!strcmp(mode, "asm")) {
        hr = assemble(src, len, called, NULL, NULL, 0, &code, &err);
    } else if (!strcmp(mode, "hlsl")) {
        struct options o;
        if (!hlsl_options(name, src, &o)) {
            free(src);
            return 0;
        }
        hr = compile(src, len, called, NULL, NULL, o.entry, o.target, o.flags, 0, &code, &err);
    } else {
        bytecode = src;
        bytecode_len = len;
    }
    if (code) {
        bytecode = code->lpVtbl->GetBufferPointer(code);
        bytecode_len = code->lpVtbl->GetBufferSize(code);
        write_blob(dir, name, "fxo", code);
    }
    if (err && err->lpVtbl->GetBufferSize(err) > 0) write_blob(dir, name, "err", err);
    write_rc(dir, name, "rc", hr);
    if (bytecode && bytecode_len) listing_and_round_trip(dir, name, called, bytecode, bytecode_len);
    release(code);
    release(err);
    free(src);
    return 1;
}

int main(int argc, char **argv) {
    if (argc != 4 || (strcmp(argv[1], "asm") && strcmp(argv[1], "hlsl") && strcmp(argv[1], "dis"))) {
        fprintf(stderr, "usage: harness asm|hlsl|dis LIST OUTDIR\n");
        return 2;
    }
    /* Microsoft's DLL from the harness's own folder, by full path: Wine has a builtin
       d3dcompiler_47 of its own, which must never answer in Microsoft's place. */
    char dll_path[MAX_PATH + 32];
    DWORD n = GetModuleFileNameA(NULL, dll_path, MAX_PATH);
    char *slash = n ? strrchr(dll_path, '\\') : NULL;
    if (!slash) {
        fprintf(stderr, "harness: cannot tell its own folder\n");
        return 3;
    }
    strcpy(slash + 1, "d3dcompiler_47.dll");
    if (GetFileAttributesA(dll_path) == INVALID_FILE_ATTRIBUTES) {
        fprintf(stderr, "harness: %s is missing; run tools/oracle/setup.sh\n", dll_path);
        return 3;
    }
    HMODULE dll = LoadLibraryA(dll_path);
    char loaded[MAX_PATH];
    if (!dll || !GetModuleFileNameA(dll, loaded, sizeof loaded) || _stricmp(loaded, dll_path)) {
        fprintf(stderr, "harness: %s does not load as itself (error %lu); run tools/oracle/setup.sh\n",
                dll_path, (unsigned long)GetLastError());
        return 3;
    }
    assemble = (assemble_fn)GetProcAddress(dll, "D3DAssemble");
    disassemble = (disassemble_fn)GetProcAddress(dll, "D3DDisassemble");
    compile = (compile_fn)GetProcAddress(dll, "D3DCompile");
    if (!assemble || !disassemble || !compile) {
        fprintf(stderr, "harness: d3dcompiler_47.dll lacks D3DAssemble, D3DDisassemble or D3DCompile\n");
        return 3;
    }
    size_t len;
    char *list = read_all(argv[2], &len);
    if (!list) {
        fprintf(stderr, "harness: cannot read the list %s\n", argv[2]);
        return 2;
    }
    if (!SetCurrentDirectoryA("C:\\")) {
        fprintf(stderr, "harness: the Wine prefix has no C:\\\n");
        return 3;
    }
    int inputs = 0, answered = 0;
    char *save = NULL;
    for (char *line = strtok_r(list, "\r\n", &save); line; line = strtok_r(NULL, "\r\n", &save)) {
        const char *dir = argv[3], *given = NULL;
        char *tab = strchr(line, '\t');
        if (tab) {
            *tab = 0, dir = tab + 1;
            tab = strchr(dir, '\t');
            if (tab) *tab = 0, given = tab + 1;
        }
        inputs++;
        answered += answer(argv[1], line, dir, given);
    }
    free(list);
    fprintf(stderr, "harness: %d of %d inputs answered\n", answered, inputs);
    return (answered == inputs && failures == 0) ? 0 : 1;
}
