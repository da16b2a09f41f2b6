#!/usr/bin/env python3
"""Writes the generated inputs of the malformed-input corpus (tests/corpus/): the sources, scenes,
meshes, images (PNG and EXR written byte by byte), glTF/GLB files and command lines. Deterministic
(fixed seeds); golden outputs (`expected`) are written by the test with RTC_BLESS=1, not here."""
import base64, copy, json, os, random, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))

def sources():
    os.chdir(os.path.join(HERE, 'sources'))
    HDR = 'import "std/cameras/pinhole.rt";\nimport "std/materials/lambert.rt";\nimport "std/lights/point.rt";\n'
    def scene(body):
        return HDR + "\nscene s {\n    camera Pinhole {}\n" + body + "\n}\n"
    cases = {
     # lexical
     "empty_file": "",
     "only_comments": "// nothing here\n/* and nothing */\n",
     "unterminated_block_comment": "fn f() {}\n/* never closed\n",
     "unterminated_string": 'import "std/cameras/pinhole.rt;\n',
     "nul_byte": "fn f() -> f32 { return 1.0; }\x00\n",
     "stray_characters": "fn f() -> f32 { return 1.0 $ 2.0; }\n",
     "unicode_identifier": "fn f() -> f32 { let größe = 1.0; return größe; }\n",
     "emoji_in_code": "fn f() -> f32 { return 1.0; } 🙂\n",
     "huge_integer": "const A: u32 = 99999999999999999999999999u;\n",
     "i32_overflow": "const A: i32 = 2147483648i;\n",
     "u32_negative": "const A: u32 = -1u;\n",
     "f32_overflow_literal": "const A: f32 = 1e39;\n",
     "f32_underflow_literal": "const A: f32 = 1e-50;\n",
     "malformed_number": "const A: f32 = 1.0e;\n",
     "hex_float": "const A: f32 = 0x1.8p3;\n",
     "unknown_suffix": "const A: f32 = 1.0q;\n",
     "bad_escape": 'import "std/\\q.rt";\n',
     "bom_and_crlf": "\ufefffn f() -> f32 {\r\n    return 1.0;\r\n}\r\n",
     "very_long_identifier": "fn " + "a"*5000 + "() -> f32 { return 1.0; }\n",
     # syntax
     "missing_semicolon": "fn f() -> f32 { let a = 1.0 return a; }\n",
     "unclosed_brace": "fn f() -> f32 { return 1.0;\n",
     "extra_closing_brace": "fn f() -> f32 { return 1.0; } }\n",
     "deep_parens": "const A: f32 = " + "("*3000 + "1.0" + ")"*3000 + ";\n",
     "deep_unary": "const A: f32 = " + "-"*5000 + "1.0;\n",
     "deep_blocks": "fn f() {" + "{"*3000 + "}"*3000 + "}\n",
     "unknown_attribute": "@shiny\nfn f() {}\n",
     "struct_literal_in_condition": "struct S { a: f32 }\nfn f() { if S { a: 1.0 }.a > 0.0 { } }\n",
     "assign_to_call": "fn g() -> f32 { return 1.0; }\nfn f() { g() = 2.0; }\n",
     "item_in_function": "fn f() { struct S { a: f32 } }\n",
     "parse_error_then_scene": HDR + "scene s {\n    camera Pinhole { fov: 40.0 \n    object o { geometry: cube_mesh(), material: Lambert {} }\n}\n",
     "parse_error_in_function_body": "fn f() -> f32 {\n    let unused = 1.0;\n    let x = (2.0 + ;\n    return x;\n}\n",
     # modules
     "import_missing_file": 'import "nope/missing.rt";\n',
     "import_absolute_path": 'import "/etc/passwd";\n',
     "import_parent_escape": 'import "../../../../etc/hostname";\n',
     "import_itself": 'import "import_itself.rt";\nfn f() {}\n',
     "import_directory": 'import "std/cameras";\n',
     "import_after_item": 'fn f() {}\nimport "std/lights/point.rt";\n',
     # types and expressions
     "mismatched_types": "fn f() -> f32 { let a: f32 = true; return a; }\n",
     "bad_operator": "fn f() -> bool { return true + 1.0; }\n",
     "wrong_arg_count": "fn g(a: f32) -> f32 { return a; }\nfn f() -> f32 { return g(1.0, 2.0); }\n",
     "no_builtin_overload": "fn f() -> f32 { return dot(1.0, true); }\n",
     "bad_swizzle": "fn f() -> f32 { let v = vec3f(1.0); return v.w; }\n",
     "constant_index_out_of_range": "fn f() -> f32 { var a: array<f32, 4u>; return a[7]; }\n",
     "negative_array_size": "const N: i32 = -3i;\nfn f() { var a: array<f32, N>; }\n",
     "zero_array_size": "fn f() { var a: array<f32, 0u>; }\n",
     "integer_division_by_zero_const": "const A: u32 = 1u / 0u;\n",
     "const_nan": "const A: f32 = 0.0 / 0.0;\n",
     "const_inf": "const A: f32 = 1e38 * 1e38;\n",
     "const_sqrt_negative": "const A: f32 = sqrt(-1.0);\n",
     "shift_overflow_const": "const A: u32 = 1u << 40u;\n",
     "non_constant_const": "fn g() -> f32 { return 1.0; }\nconst A: f32 = g();\n",
     "undefined_name": "fn f() -> f32 { return nope; }\n",
     "undefined_type": "fn f(a: Nope) {}\n",
     "duplicate_item": "fn f() {}\nfn f() {}\n",
     "struct_cycle": "struct A { b: B }\nstruct B { a: A }\n",
     "const_cycle": "const A: f32 = B;\nconst B: f32 = A;\n",
     # statements
     "assign_immutable": "fn f() { let a = 1.0; a = 2.0; }\n",
     "break_outside_loop": "fn f() { break; }\n",
     "missing_return": "fn f(x: f32) -> f32 { if x > 0.0 { return 1.0; } }\n",
     "non_bool_condition": "fn f() { if 1.0 { } }\n",
     "for_range_mixed": "fn f() { for i in 0u..3i { } }\n",
     "unreachable_code": "fn f() -> f32 { return 1.0; let a = 2.0; }\n",
     "infinite_loop_accepted": "fn f() -> f32 { var x = 0.0; loop { x += 1.0; } return x; }\n",
     # recursion and programs
     "direct_recursion": "fn f(x: f32) -> f32 { return f(x); }\n",
     "mutual_recursion": "fn f(x: f32) -> f32 { return g(x); }\nfn g(x: f32) -> f32 { return f(x); }\n",
     "program_wrong_signature": "@material\nstruct M { a: f32 = 1.0 }\n@closest_hit\nfn shade(m: M) -> vec3f { return vec3f(0.0); }\n",
     "program_on_struct": "@closest_hit\nstruct M { a: f32 }\n",
     "two_roles": "@material @camera\nstruct M { a: f32 = 1.0 }\n",
     "intrinsic_outside_program": "fn f() -> u32 { return light_count(); }\nconst A: u32 = 1u;\n",
     "unbounded_spawn": "@material\nstruct M { n: u32 = 3u }\n@secondary_rays\nfn rays(m: M, ray: Ray, hit: Hit) {\n    for i in 0u..m.n { spawn(hit.normal, vec3f(1.0)); }\n}\n@closest_hit\nfn shade(m: M, ray: Ray, hit: Hit, secondary: vec3f) -> vec3f { return secondary; }\n",
     # resource limits: sizes the targets cannot hold must be diagnostics, never an abort or an ICE
 "const_array_u32_max": "const BIG: array<f32, 4294967295u> = array<f32, 4294967295u>();\n",
 "const_array_hundred_million": "const BIG: array<f32, 100000000u> = array<f32, 100000000u>();\n",
 "local_array_billion_vec4": "fn f() -> f32 { var a: array<vec4f, 1000000000u>; return a[0].x; }\n",
 "local_array_million_vec4": "fn f() -> f32 { var a: array<vec4f, 1000000u>; return a[0].x; }\n",
 "nested_array_overflow": "struct S { a: array<array<vec4f, 65536u>, 65536u> }\n",
 "struct_of_huge_arrays": "struct S { a: array<f32, 30000000u>, b: array<f32, 30000000u> }\nfn f(s: S) -> f32 { return s.a[0]; }\n",
 "unstorable_field": "@material\nstruct M { a: array<f32, 4u> = array<f32, 4u>(), }\n",
    }
    for name, text in cases.items():
        mode = 'wb'
        with open(name + '.rt', 'wb') as f:
            f.write(text.encode('utf-8'))
    # invalid UTF-8
    with open('invalid_utf8.rt','wb') as f:
        f.write(b"fn f() -> f32 { return 1.0; }\n// \xff\xfe\xc3\x28 bad bytes\n")
    # binary garbage
    r = random.Random(21)
    with open('binary_garbage.rt','wb') as f:
        f.write(bytes(r.randrange(256) for _ in range(2048)))
    print(len(os.listdir('.')))


def scenes():
    os.chdir(os.path.join(HERE, 'scenes'))
    HDR = 'import "std/cameras/pinhole.rt";\nimport "std/materials/lambert.rt";\nimport "std/materials/glass.rt";\nimport "std/lights/point.rt";\nimport "std/miss/gradient.rt";\n'
    def sc(body, name="s", cam='    camera Pinhole { position: vec3f(0.0, 1.0, 5.0) }\n'):
        return HDR + f"\nscene {name} {{\n" + cam + body + "}\n"
    OBJ = '    object o { geometry: cube_mesh(), material: Lambert {} }\n'
    LIGHT = '    light l PointLight { position: vec3f(0.0, 3.0, 0.0) }\n'
    cases = {
     "no_camera": sc(OBJ, cam=""),
     "camera_twice": sc(OBJ + '    camera Pinhole {}\n'),
     "unknown_entry": sc(OBJ + '    thing t {}\n'),
     "material_as_geometry": sc('    object o { geometry: Lambert {}, material: Lambert {} }\n'),
     "geometry_missing": sc('    object o { material: Lambert {} }\n'),
     "unknown_struct": sc('    object o { geometry: cube_mesh(), material: Shiny {} }\n'),
     "field_wrong_type": sc('    object o { geometry: cube_mesh(), material: Lambert { albedo: true } }\n'),
     "field_unknown": sc('    object o { geometry: cube_mesh(), material: Lambert { colour: vec3f(1.0) } }\n'),
     "field_twice": sc('    object o { geometry: cube_mesh(), material: Lambert { albedo: vec3f(1.0), albedo: vec3f(0.5) } }\n'),
     "object_name_twice": sc(OBJ + OBJ),
     "settings_twice": sc('    settings { width: 64 }\n    settings { height: 64 }\n' + OBJ),
     "width_zero": sc('    settings { width: 0 }\n' + OBJ),
     "width_huge": sc('    settings { width: 100000 }\n' + OBJ),
     "samples_too_many": sc('    settings { samples: 1048577 }\n' + OBJ),
     "max_depth_too_deep": sc('    settings { max_depth: 65 }\n' + OBJ),
     "max_rays_per_hit_zero": sc('    settings { max_rays_per_hit: 0 }\n' + OBJ),
     "max_rays_per_hit_drops_refraction": sc('    settings { max_rays_per_hit: 1 }\n    object g { geometry: sphere_mesh(2u), material: Glass {} }\n' + LIGHT),
     "unknown_setting": sc('    settings { quality: 3 }\n' + OBJ),
     "setting_wrong_type": sc('    settings { width: 64.5 }\n' + OBJ),
     "sphere_mesh_too_fine": sc('    object o { geometry: sphere_mesh(30u), material: Lambert {} }\n' + LIGHT),
     "scale_tiny": sc('    object o { geometry: cube_mesh(), material: Lambert {}, transform: scale(1e-30) }\n' + LIGHT),
     "scale_huge": sc('    object o { geometry: cube_mesh(), material: Lambert {}, transform: scale(1e30) }\n' + LIGHT),
     "scale_zero": sc('    object o { geometry: cube_mesh(), material: Lambert {}, transform: scale(0.0) }\n' + LIGHT),
     "transform_nan": sc('    object o { geometry: cube_mesh(), material: Lambert {}, transform: translate(vec3f(0.0 / 0.0)) }\n' + LIGHT),
     "fov_zero": sc(OBJ + LIGHT, cam='    camera Pinhole { fov: 0.0 }\n'),
     "fov_underflow": sc(OBJ + LIGHT, cam='    camera Pinhole { fov: 1e-30 * 1e-30 }\n'),
     "fov_180": sc(OBJ + LIGHT, cam='    camera Pinhole { fov: 180.0 }\n'),
     "camera_looks_at_itself": sc(OBJ + LIGHT, cam='    camera Pinhole { position: vec3f(1.0), look_at: vec3f(1.0) }\n'),
     "camera_up_parallel": sc(OBJ + LIGHT, cam='    camera Pinhole { position: vec3f(0.0, 5.0, 0.0), look_at: vec3f(0.0), up: vec3f(0.0, 1.0, 0.0) }\n'),
     "light_intensity_inf": sc(OBJ + '    light l PointLight { intensity: 1e38 * 10.0 }\n'),
     "albedo_nan": sc('    object o { geometry: cube_mesh(), material: Lambert { albedo: vec3f(0.0 / 0.0) } }\n' + LIGHT),
     "non_constant_value": HDR + "fn f() -> f32 { return 1.0; }\nscene s {\n    camera Pinhole { fov: f() }\n" + OBJ + "}\n",
     "let_unused_and_shadowed": sc('    let a = Lambert {};\n    let a = Lambert { albedo: vec3f(0.2) };\n' + OBJ),
     "model_and_no_camera_file_missing": HDR + 'scene s {\n    model "missing.glb" {}\n}\n',
     "two_scenes_same_name": sc(OBJ) + "\n" + sc(OBJ),
     "no_scene_only_library": HDR + "fn f() -> f32 { return 1.0; }\n",
     "load_mesh_absolute": sc('    object o { geometry: load_mesh("/etc/passwd"), material: Lambert {} }\n' + LIGHT),
     "load_image_parent_escape": HDR + 'import "std/miss/skybox.rt";\n' + 'scene s {\n    camera Pinhole {}\n    background Skybox { image: load_image("../../../../etc/hostname") }\n' + OBJ + '}\n',
     "load_mesh_not_string": sc('    object o { geometry: load_mesh(3.0), material: Lambert {} }\n'),
     "empty_scene": HDR + "scene s {}\n",
    }
    for name, text in cases.items():
        open(name + '.rt','w').write(text)
    print(len(cases))


def assets():
    root=HERE
    HDR = 'import "std/cameras/pinhole.rt";\nimport "std/materials/lambert.rt";\nimport "std/lights/point.rt";\n'
    def case(cat, name, files, args):
        d=os.path.join(root,cat,name); os.makedirs(d, exist_ok=True)
        for fn, data in files.items():
            p=os.path.join(d,fn); os.makedirs(os.path.dirname(p), exist_ok=True)
            if isinstance(data,str): data=data.encode()
            open(p,'wb').write(data)
        open(os.path.join(d,'args'),'w').write(args+"\n")
    def mesh_scene(path):
        return HDR + f'\nscene s {{\n    camera Pinhole {{ position: vec3f(0.0, 1.0, 5.0) }}\n    object o {{ geometry: load_mesh("{path}"), material: Lambert {{}} }}\n    light l PointLight {{ position: vec3f(0.0, 3.0, 0.0) }}\n}}\n'
    TRI = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
    meshes = {
     "missing_file": ({}, "m.obj"),
     "empty_file": ({"m.obj": ""}, "m.obj"),
     "vertices_only": ({"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\n"}, "m.obj"),
     "index_out_of_range": ({"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"}, "m.obj"),
     "index_zero": ({"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"}, "m.obj"),
     "negative_index_too_far": ({"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -7\n"}, "m.obj"),
     "nan_vertex": ({"m.obj": "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}, "m.obj"),
     "inf_vertex": ({"m.obj": "v inf 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}, "m.obj"),
     "overflowing_vertex": ({"m.obj": "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}, "m.obj"),
     "non_numeric_vertex": ({"m.obj": "v a b c\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}, "m.obj"),
     "binary_garbage": ({"m.obj": bytes(random.Random(7).randrange(256) for _ in range(4096))}, "m.obj"),
     "invalid_utf8": ({"m.obj": TRI.encode() + b"# \xff\xfe\n"}, "m.obj"),
     "lines_only": ({"m.obj": "v 0 0 0\nv 1 0 0\nl 1 2\n"}, "m.obj"),
     "degenerate_triangles_only": ({"m.obj": "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 1 1 1\n"}, "m.obj"),
     "absolute_path": ({}, "/etc/passwd"),
     "parent_escape": ({}, "../../../../../../etc/hostname"),
     "directory_as_mesh": ({"sub/keep.txt": "x"}, "sub"),
     "png_as_mesh": ({"m.obj": b"\x89PNG\r\n\x1a\n" + b"\x00"*64}, "m.obj"),
     "missing_mtllib": ({"m.obj": "mtllib nope.mtl\nusemtl red\n" + TRI}, "m.obj"),
     "huge_polygon": ({"m.obj": "".join(f"v {i} {i%7} 0\n" for i in range(3000)) + "f " + " ".join(str(i+1) for i in range(3000)) + "\n"}, "m.obj"),
     "normal_index_out_of_range": ({"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//5 3//1\n"}, "m.obj"),
     "texcoord_nan": ({"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt nan 0\nf 1/1 2/1 3/1\n"}, "m.obj"),
    }
    for name,(files,path) in meshes.items():
        f=dict(files); f["scene.rt"]=mesh_scene(path)
        case("meshes", name, f, "check --assets scene.rt")

    # ---- images ----
    def png_chunk(t, data):
        return struct.pack(">I", len(data)) + t + data + struct.pack(">I", zlib.crc32(t+data) & 0xffffffff)
    def png(w, h, rows=None, color_type=2, depth=8, bad_crc=False, truncate=None):
        ihdr = struct.pack(">IIBBBBB", w, h, depth, color_type, 0, 0, 0)
        ch = {0:1,2:3,4:2,6:4}[color_type]*depth//8
        if rows is None:
            rows = b"".join(b"\x00" + bytes([200]*(w*ch)) for _ in range(h))
        data = b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", zlib.compress(rows)) + png_chunk(b"IEND", b"")
        if bad_crc:
            data = data[:29] + bytes([data[29]^0xff]) + data[30:]
        if truncate: data = data[:truncate]
        return data
    def exr(w, h, values):
        # uncompressed scanline EXR, channels B,G,R float
        def attr(name, typ, data): return name.encode()+b"\0"+typ.encode()+b"\0"+struct.pack("<i",len(data))+data
        chl = b"".join(c.encode()+b"\0"+struct.pack("<iBBBBii",2,0,0,0,0,1,1) for c in "BGR") + b"\0"
        hdr = b"\x76\x2f\x31\x01" + struct.pack("<I",2)
        hdr += attr("channels","chlist",chl)
        hdr += attr("compression","compression",b"\0")
        hdr += attr("dataWindow","box2i",struct.pack("<iiii",0,0,w-1,h-1))
        hdr += attr("displayWindow","box2i",struct.pack("<iiii",0,0,w-1,h-1))
        hdr += attr("lineOrder","lineOrder",b"\0")
        hdr += attr("pixelAspectRatio","float",struct.pack("<f",1.0))
        hdr += attr("screenWindowCenter","v2f",struct.pack("<ff",0,0))
        hdr += attr("screenWindowWidth","float",struct.pack("<f",1.0))
        hdr += b"\0"
        table_start = len(hdr); lines=[]
        for y in range(h):
            row = b""
            for c in range(3):
                for x in range(w):
                    row += struct.pack("<f", values(x,y,2-c))
            lines.append(struct.pack("<ii", y, len(row)) + row)
        off = table_start + 8*h; table=b""
        for l in lines:
            table += struct.pack("<Q", off); off += len(l)
        return hdr + table + b"".join(lines)
    def img_scene(path):
        return HDR + 'import "std/materials/unlit_texture.rt";\n' + f'\nscene s {{\n    camera Pinhole {{ position: vec3f(0.0, 1.0, 5.0) }}\n    object o {{ geometry: quad_mesh(), material: UnlitTexture {{ texture: load_image("{path}") }} }}\n}}\n'
    nan=float('nan'); inf=float('inf')
    images = {
     "missing_file": ({}, "t.png"),
     "empty_file": ({"t.png": b""}, "t.png"),
     "truncated_png": ({"t.png": png(4,4,truncate=40)}, "t.png"),
     "png_bad_crc": ({"t.png": png(4,4,bad_crc=True)}, "t.png"),
     "text_named_png": ({"t.png": "this is not an image\n"}, "t.png"),
     "garbage_jpeg": ({"t.jpg": b"\xff\xd8\xff\xe0" + bytes(random.Random(3).randrange(256) for _ in range(300))}, "t.jpg"),
     "garbage_exr": ({"t.exr": b"\x76\x2f\x31\x01" + b"\x02\0\0\0garbage"*10}, "t.exr"),
     "garbage_hdr": ({"t.hdr": b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n\x01\x02"}, "t.hdr"),
     "exr_with_nan_texels": ({"t.exr": exr(4,4,lambda x,y,c: nan if (x+y)%3==0 else 0.5)}, "t.exr"),
     "exr_with_inf_texels": ({"t.exr": exr(4,4,lambda x,y,c: inf if x==1 else 0.25)}, "t.exr"),
     "exr_valid": ({"t.exr": exr(4,4,lambda x,y,c: 0.1*(x+c))}, "t.exr"),
     "unsupported_extension": ({"t.bmp": b"BM" + b"\0"*60}, "t.bmp"),
     "no_extension": ({"t": png(4,4)}, "t"),
     "huge_dimensions_header": ({"t.png": png(200000,200000,rows=b"\x00")}, "t.png"),
     "zero_width_header": ({"t.png": png(0,4,rows=b"\x00"*4)}, "t.png"),
     "directory_as_image": ({"d/keep.txt": "x"}, "d"),
     "absolute_path": ({}, "/etc/hostname"),
     "parent_escape": ({}, "../../../../../../etc/hostname"),
     "png_16_bit_grey_alpha": ({"t.png": png(2,2,color_type=4,depth=16)}, "t.png"),
     "png_wrong_extension_jpg": ({"t.jpg": png(4,4)}, "t.jpg"),
    }
    for name,(files,path) in images.items():
        f=dict(files); f["scene.rt"]=img_scene(path)
        case("images", name, f, "check --assets scene.rt")
    print(len(meshes), len(images))


def gltf():
    root=HERE
    def case(name, files, args):
        d=os.path.join(root,'gltf',name); os.makedirs(d, exist_ok=True)
        for fn, data in files.items():
            p=os.path.join(d,fn); os.makedirs(os.path.dirname(p), exist_ok=True)
            if isinstance(data,str): data=data.encode()
            open(p,'wb').write(data)
        open(os.path.join(d,'args'),'w').write(args+"\n")
    pos = struct.pack("<9f", 0,0,0, 1,0,0, 0,1,0)
    idx = struct.pack("<3H", 0,1,2) + b"\0\0"
    BIN = pos + idx
    def uri(b): return "data:application/octet-stream;base64," + base64.b64encode(b).decode()
    BASE = {
      "asset": {"version": "2.0"},
      "scene": 0,
      "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.2, 1.0]}}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "buffers": [{"byteLength": 44, "uri": "m.bin"}],
    }
    def variant(f):
        g = copy.deepcopy(BASE); f(g); return json.dumps(g, indent=1)
    def png_chunk(t, data): return struct.pack(">I", len(data)) + t + data + struct.pack(">I", zlib.crc32(t+data) & 0xffffffff)
    GOOD_PNG = b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", struct.pack(">IIBBBBB",2,2,8,2,0,0,0)) + png_chunk(b"IDAT", zlib.compress(b"\0"+b"\xff"*6+b"\0"+b"\x80"*6)) + png_chunk(b"IEND", b"")
    def with_image(u):
        def f(g):
            g["images"]=[{"uri": u}]; g["textures"]=[{"source":0}]
            g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]={"index":0}
            g["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"]=0  # reuse positions? wrong type; fix below
            del g["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"]
        return f
    def setp(path, value):
        def f(g):
            o=g
            for k in path[:-1]: o=o[k]
            o[path[-1]]=value
        return f
    def deep_nodes(n):
        def f(g):
            g["nodes"]=[{"children":[i+1]} for i in range(n)] + [{"mesh":0}]
        return f
    cases = {
     "not_json": ("model.gltf", {"model.gltf": "this is { not json"}),
     "empty_file": ("model.gltf", {"model.gltf": ""}),
     "json_array": ("model.gltf", {"model.gltf": "[1, 2, 3]"}),
     "missing_asset": ("model.gltf", {"model.gltf": variant(lambda g: g.pop("asset")), "m.bin": BIN}),
     "version_3": ("model.gltf", {"model.gltf": variant(setp(["asset","version"],"3.0")), "m.bin": BIN}),
     "buffer_file_missing": ("model.gltf", {"model.gltf": variant(lambda g: None)}),
     "buffer_uri_absolute": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"uri"],"/etc/passwd"))}),
     "buffer_uri_parent": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"uri"],"../../../../../../etc/hostname"))}),
     "buffer_uri_percent_encoded": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"uri"],"%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/hostname"))}),
     "buffer_uri_file_scheme": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"uri"],"file:///etc/passwd"))}),
     "buffer_uri_backslashes": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"uri"],"..\\..\\..\\..\\etc\\hostname"))}),
     "buffer_uri_http": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"uri"],"http://example.invalid/m.bin"))}),
     "buffer_bad_base64": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"uri"],"data:application/octet-stream;base64,@@@@"))}),
     "buffer_shorter_than_declared": ("model.gltf", {"model.gltf": variant(setp(["buffers",0,"byteLength"],4000)), "m.bin": BIN}),
     "image_uri_absolute": ("model.gltf", {"model.gltf": variant(with_image("/etc/hostname")), "m.bin": BIN}),
     "image_uri_parent": ("model.gltf", {"model.gltf": variant(with_image("../../../../../../etc/hostname")), "m.bin": BIN}),
     "image_corrupt_png": ("model.gltf", {"model.gltf": variant(with_image("tex.png")), "m.bin": BIN, "tex.png": GOOD_PNG[:30] + b"\0"*20}),
     "image_missing": ("model.gltf", {"model.gltf": variant(with_image("tex.png")), "m.bin": BIN}),
     "accessor_count_beyond_view": ("model.gltf", {"model.gltf": variant(setp(["accessors",0,"count"],300)), "m.bin": BIN}),
     "accessor_huge_count": ("model.gltf", {"model.gltf": variant(setp(["accessors",0,"count"],4294967295)), "m.bin": BIN}),
     "accessor_bad_component_type": ("model.gltf", {"model.gltf": variant(setp(["accessors",0,"componentType"],5130)), "m.bin": BIN}),
     "position_as_vec2": ("model.gltf", {"model.gltf": variant(setp(["accessors",0,"type"],"VEC2")), "m.bin": BIN}),
     "indices_out_of_range": ("model.gltf", {"model.gltf": variant(lambda g: None), "m.bin": pos + struct.pack("<3H",0,1,77) + b"\0\0"}),
     "view_offset_beyond_buffer": ("model.gltf", {"model.gltf": variant(setp(["bufferViews",1,"byteOffset"],1000)), "m.bin": BIN}),
     "byte_stride_too_small": ("model.gltf", {"model.gltf": variant(setp(["bufferViews",0,"byteStride"],4)), "m.bin": BIN}),
     "accessor_without_buffer_view": ("model.gltf", {"model.gltf": variant(lambda g: g["accessors"].append({"componentType":5126,"count":3,"type":"VEC3"}) or g["meshes"][0]["primitives"][0]["attributes"].__setitem__("NORMAL",2)), "m.bin": BIN}),
     "extras_of_every_type": ("model.gltf", {"model.gltf": variant(lambda g: (g.__setitem__("extras", [1,"two",None]), g["nodes"][0].__setitem__("extras", 5), g["meshes"][0].__setitem__("extras", "text"), g["materials"][0].__setitem__("extras", True))), "m.bin": BIN}),
     "node_cycle": ("model.gltf", {"model.gltf": variant(lambda g: g.__setitem__("nodes", [{"children":[1]},{"children":[0],"mesh":0}])), "m.bin": BIN}),
     "node_index_out_of_range": ("model.gltf", {"model.gltf": variant(setp(["scenes",0,"nodes"],[5])), "m.bin": BIN}),
     "mesh_index_out_of_range": ("model.gltf", {"model.gltf": variant(setp(["nodes",0,"mesh"],9)), "m.bin": BIN}),
     "material_index_out_of_range": ("model.gltf", {"model.gltf": variant(setp(["meshes",0,"primitives",0,"material"],4)), "m.bin": BIN}),
     "number_out_of_range": ("model.gltf", {"model.gltf": variant(setp(["nodes",0,"translation"],[0,0,0])).replace('"translation": [\n    0,', '"translation": [\n    1e400,'), "m.bin": BIN}),
     "singular_node_matrix": ("model.gltf", {"model.gltf": variant(setp(["nodes",0,"matrix"],[0]*16)), "m.bin": BIN}),
     "huge_node_scale": ("model.gltf", {"model.gltf": variant(setp(["nodes",0,"scale"],[1e30,1e30,1e30])), "m.bin": BIN}),
     "deep_node_hierarchy": ("model.gltf", {"model.gltf": variant(deep_nodes(5000)), "m.bin": BIN}),
     "points_primitive": ("model.gltf", {"model.gltf": variant(setp(["meshes",0,"primitives",0,"mode"],0)), "m.bin": BIN}),
     "no_meshes_at_all": ("model.gltf", {"model.gltf": json.dumps({"asset":{"version":"2.0"},"scenes":[{"nodes":[]}],"scene":0})}),
     "required_extension_unknown": ("model.gltf", {"model.gltf": variant(lambda g: g.__setitem__("extensionsRequired",["KHR_draco_mesh_compression"]) or g.__setitem__("extensionsUsed",["KHR_draco_mesh_compression"])), "m.bin": BIN}),
     "sparse_accessor": ("model.gltf", {"model.gltf": variant(lambda g: g["accessors"][0].__setitem__("sparse", {"count":1,"indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0}})), "m.bin": BIN}),
    }
    for name,(arg,files) in cases.items():
        case(name, files, "check --assets " + arg)
    # GLB cases
    gj = copy.deepcopy(BASE); gj["buffers"]=[{"byteLength":44}]
    J = json.dumps(gj).encode(); J += b" " * ((4 - len(J)%4)%4)
    def glb(json_bytes, bin_bytes, magic=b"glTF", version=2, total=None):
        body = struct.pack("<I4s", len(json_bytes), b"JSON") + json_bytes
        if bin_bytes is not None: body += struct.pack("<I4s", len(bin_bytes), b"BIN\0") + bin_bytes
        t = 12 + len(body) if total is None else total
        return magic + struct.pack("<II", version, t) + body
    good = glb(J, BIN)
    glbs = {
     "glb_wrong_magic": glb(J, BIN, magic=b"gLTF"),
     "glb_version_1": glb(J, BIN, version=1),
     "glb_truncated": good[:40],
     "glb_length_beyond_file": glb(J, BIN, total=10**6),
     "glb_json_chunk_too_long": good[:12] + struct.pack("<I", 10**6) + good[16:],
     "glb_missing_bin_chunk": glb(J, None),
     "glb_header_only": good[:12],
     "glb_json_not_utf8": glb(b"\xff\xfe" + J[2:], BIN),
    }
    for name, data in glbs.items():
        case(name, {"model.glb": data}, "check --assets model.glb")
    # a scene that names a glTF outside its folder
    case("model_entry_escapes_folder", {"scene.rt": 'import "std/miss/gradient.rt";\nscene s {\n    background SkyGradient {}\n    model "../../../../../../etc/passwd.glb" {}\n}\n'}, "check --assets scene.rt")
    case("model_entry_absolute", {"scene.rt": 'import "std/miss/gradient.rt";\nscene s {\n    background SkyGradient {}\n    model "/etc/hostname.gltf" {}\n}\n'}, "check --assets scene.rt")
    print(len(cases)+len(glbs)+2)


def cli():
    root=os.path.join(HERE, 'cli')
    SCENE = open(os.path.join(HERE, '..', '..', 'examples', 'hello', 'scene.rt')).read()
    def case(name, args, files=None):
        d=os.path.join(root,name); os.makedirs(d, exist_ok=True)
        files = {"scene.rt": SCENE} if files is None else files
        for fn, data in files.items():
            p=os.path.join(d,fn); os.makedirs(os.path.dirname(p), exist_ok=True)
            open(p,'w').write(data)
        open(os.path.join(d,'args'),'w').write(args+"\n")
    cases = {
     "render_without_arguments": "render",
     "unknown_subcommand": "frobnicate scene.rt",
     "spp_zero": "render scene.rt -o x.png --spp 0",
     "spp_too_many": "render scene.rt -o x.png --spp 1048577",
     "spp_negative": "render scene.rt -o x.png --spp -3",
     "spp_not_a_number": "render scene.rt -o x.png --spp many",
     "size_zero": "render scene.rt -o x.png --size 0x0",
     "size_too_wide": "render scene.rt -o x.png --size 100000x10",
     "size_one_number": "render scene.rt -o x.png --size 64",
     "size_overflows_u32": "render scene.rt -o x.png --size 99999999999999999999x2",
     "output_unknown_extension": "render scene.rt -o x.jpg",
     "output_folder_missing": "render scene.rt -o no/such/dir/x.png",
     "output_is_a_folder": "render scene.rt -o sub.png",
     "output_missing": "render scene.rt",
     "scene_file_missing": "render missing.rt -o x.png",
     "unknown_scene_name": "render scene.rt -o x.png --scene nope",
     "unknown_adapter": "render scene.rt -o x.png --adapter quantum",
     "unknown_bvh_preset": "render scene.rt -o x.png --bvh slow",
     "check_missing_path": "check nope.rt",
     "check_empty_folder": "check empty",
     "compile_unknown_target": "compile scene.rt --target wgsl,cuda",
     "compile_unknown_emit": "compile scene.rt --emit bytecode",
     "check_unknown_message_format": "check scene.rt --message-format yaml",
     "bench_spp_list_zero": "bench scene.rt --spp-list 0,1",
     "bench_spp_list_huge": "bench scene.rt --spp-list 1,2,99999999",
     "render_a_folder": "render sub -o x.png",
     "render_an_image_as_scene": "render picture.png -o x.png",
     "watch_missing_file": "watch nope.rt -o x.png",
     "unknown_flag": "render scene.rt -o x.png --loop 0..10",
     "frames_without_number": "render scene.rt -o x.png --frames 0..10",
     "frames_backwards": "render scene.rt -o x_%04d.png --frames 5..2",
     "shard_index_too_large": "render scene.rt -o x_%04d.png --frames 0..4 --shard 4/4",
     "shard_count_zero": "render scene.rt -o x_%04d.png --shard 0/0",
     "color_bad_value": "check scene.rt --color purple",
     "stdlib_folder_missing": "check scene.rt --stdlib no/such/std",
    }
    for name, args in cases.items():
        files = {"scene.rt": SCENE}
        if name == "output_is_a_folder": files["sub.png/keep.txt"] = "x"
        if name == "render_a_folder": files["sub/keep.txt"] = "x"
        if name == "check_empty_folder": files["empty/notes.txt"] = "no .rt here"
        if name == "render_an_image_as_scene": files["picture.png"] = "\x89PNG not really"
        case(name, args, files)
    print(len(cases))


if __name__ == "__main__":
    for d in ("sources", "scenes", "gltf", "images", "meshes", "cli"):
        os.makedirs(os.path.join(HERE, d), exist_ok=True)
    sources()
    scenes()
    assets()
    gltf()
    cli()
