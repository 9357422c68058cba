//! Microsoft's error codes: for each kind of refusal, the `X####` code that
//! `D3DAssemble` (d3dcompiler_47.dll) gives for the same input, so that a
//! ps30 error can be looked up with the code a user already met in fxc's
//! output or a game's log.
//!
//! This is the one table of them: every check that refuses a shader names
//! the constant for its rule here, never a literal code. Each code was read
//! from Microsoft's answer to the probes of `tests/oracle/corpus/asm/`
//! (`tests/oracle/accept.rs` checks every refusal against those answers);
//! the comment beside it is Microsoft's own message, shortened.

/// A Microsoft `X####` code.
pub type Code = &'static str;

// --- the preprocessor and the lexer --------------------------------------
/// "comment continues past end of file" (a `/*` never closed).
pub const UNCLOSED_COMMENT: Code = "X1001";
/// "decimal value truncated to 64 bits".
pub const NUMBER_TOO_LONG: Code = "X1004";
/// "syntax error" in a preprocessor directive or `#if` expression.
pub const PREPROCESSOR_SYNTAX: Code = "X1500";
/// "unexpected end of file" (an `#if` never closed).
pub const PREPROCESSOR_EOF: Code = "X1502";
/// "division by zero in preprocessor expression".
pub const PREPROCESSOR_DIVIDE_BY_ZERO: Code = "X1503";
/// "invalid preprocessor command".
pub const PREPROCESSOR: Code = "X1504";
/// "No include handler specified, can't perform a #include".
pub const INCLUDE: Code = "X1505";
/// "unexpected #elif" (no `#if` open).
pub const UNEXPECTED_ELIF: Code = "X1508";
/// "unexpected #else" (no `#if` open).
pub const UNEXPECTED_ELSE: Code = "X1509";
/// "unexpected #endif" (no `#if` open).
pub const UNEXPECTED_ENDIF: Code = "X1510";
/// "duplicate macro parameter".
pub const MACRO_PARAMETER_TWICE: Code = "X1511";
/// "unexpected #elif following #else".
pub const ELIF_AFTER_ELSE: Code = "X1513";
/// "unexpected #else following #else".
pub const ELSE_AFTER_ELSE: Code = "X1514";
/// "unexpected end of file in macro expansion" (a call's `(` never closed).
pub const MACRO_CALL_UNCLOSED: Code = "X1515";
/// "not enough actual parameters for macro" (Microsoft says so for too
/// many as well).
pub const MACRO_ARGUMENTS: Code = "X1516";
/// "macro redefinition" (a warning).
pub const MACRO_REDEFINED: Code = "X1519";
/// "unknown pragma ignored" (a warning).
pub const UNKNOWN_PRAGMA: Code = "X3568";

// --- the assembler's grammar ------------------------------------------------
/// "syntax error : unexpected token": an unknown mnemonic or modifier, a
/// wrong operand count, a literal where a register goes, stray text.
pub const SYNTAX: Code = "X2000";
/// "shader version expected": no `ps_3_0` first (a byte-order mark, text in
/// another encoding, an unknown version).
pub const VERSION: Code = "X2001";
/// "invalid mask".
pub const MASK: Code = "X2003";
/// "invalid swizzle".
pub const SWIZZLE: Code = "X2004";
/// "invalid register": an unknown name, a number out of range, a register
/// that cannot be indexed, an unknown source modifier.
pub const REGISTER: Code = "X2005";
/// "scalar registers cannot be masked / swizzled" (oDepth, vFace, aL, b#),
/// found by the grammar before any rule about where a register may go.
pub const SCALAR: Code = "X2022";
/// "relative addressing of destination parameters is not supported in
/// this shader version".
pub const DESTINATION_RELATIVE: Code = "X2008";
/// "source modifiers are not allowed on destination parameters".
pub const DESTINATION_MODIFIER: Code = "X2014";
/// "instruction coissue is not supported in this shader version".
pub const COISSUE: Code = "X2027";
/// "source modifiers incompatible with SUB instruction" (`!` on the
/// source that sub negates).
pub const SUB_MODIFIER: Code = "X2013";
/// "complement is not supported in this shader version" (`1-r0`).
pub const COMPLEMENT: Code = "X2029";

// --- the validator: declarations and definitions ---------------------------
/// "dcl instruction should have exactly 2 parameter tokens" (a predicate
/// on a declaration).
pub const DCL_TOKENS: Code = "X5002";
/// "Unexpected DWORD count for instruction" (a predicate on a definition).
pub const DWORD_COUNT: Code = "X5005";
/// "def and dcl instructions must appear before other instructions" (dcl).
pub const DCL_TOO_LATE: Code = "X5297";
/// "Invalid register type for dcl".
pub const DCL_REGISTER: Code = "X5299";
/// "Declaration for register v# overlaps previous declaration".
pub const DCL_OVERLAP: Code = "X5301";
/// "dcl usage+index … has already been specified for an input register".
pub const DCL_USAGE_TWICE: Code = "X5304";
/// "dcl s# must be one of the following types".
pub const SAMPLER_TYPE: Code = "X5585";
/// "Destination for def instruction must be of the form c#".
pub const DEF_DESTINATION: Code = "X5587";
/// "c# already def'd in the shader".
pub const DEF_TWICE: Code = "X5594";
/// "i# already def'd in the shader".
pub const DEFI_TWICE: Code = "X5595";
/// "b# already def'd in the shader".
pub const DEFB_TWICE: Code = "X5596";
/// "vPos register already declared" (and "vFace register already
/// declared").
pub const VPOS_TWICE: Code = "X5630";
/// "z or w components of vPos … cannot be dcl'd".
pub const VPOS_MASK: Code = "X5631";
/// "def or dcl instructions must appear before other instructions" (def).
pub const DEF_TOO_LATE: Code = "X5729";
/// "Destination for defi instruction must be i# register".
pub const DEFI_DESTINATION: Code = "X5732";
/// "Destination for defb instruction must be b# register … there may be no
/// mask".
pub const DEFB_DESTINATION: Code = "X6011";
/// "Sampler s# already declared".
pub const SAMPLER_TWICE: Code = "X5769";
/// "dcl s# must not specify a writemask".
pub const SAMPLER_MASK: Code = "X5770";
/// "dcl for s register does not support any modifiers".
pub const SAMPLER_MODIFIER: Code = "X5969";
/// "dcl for vPos register does not support any modifiers".
pub const VPOS_MODIFIER: Code = "X5969";
/// "dcl usage+index positiont# cannot be used in a pixel shader".
pub const DCL_POSITIONT: Code = "X5972";
/// "dcl usage 'tessfactor' is not avaliable to the pixel shader".
pub const DCL_TESSFACTOR: Code = "X5973";
/// "dcl usage 'sample' is not avaliable to the pixel shader".
pub const DCL_SAMPLE: Code = "X5974";
/// "dcl usage+index psize# cannot be used in a pixel shader".
pub const DCL_PSIZE: Code = "X5537";
/// "dcl for input v# register must specify usage+index".
pub const DCL_USAGE: Code = "X5971";
/// "Components of register v# being read, but not declared".
pub const UNDECLARED_INPUT: Code = "X5984";
/// "Component(s) of register vPos being read, but not declared".
pub const UNDECLARED_VPOS: Code = "X5985";
/// "vFace being read, but not declared".
pub const UNDECLARED_VFACE: Code = "X5986";
/// "vPos does not have .z or .w channels in this shader model".
pub const VPOS_ZW: Code = "X6063";
/// "Sampler register s# has not been declared".
pub const UNDECLARED_SAMPLER: Code = "X5576";

// --- the validator: integer constants --------------------------------------
/// "i#.x (which represents loop or rep iteration count) cannot be negative".
pub const COUNT_NEGATIVE: Code = "X5990";
/// "i#.x … cannot be greater than 255".
pub const COUNT_TOO_LARGE: Code = "X5995";
/// "i#.y (which represents loop initial value) must be in the range [0, 255]".
pub const LOOP_START: Code = "X5558";
/// "i#.z (which represents loop step value) must be in the range [-128, 127]".
pub const LOOP_STEP: Code = "X5560";
/// "i#.w has no meaning; it must simply be 0".
pub const LOOP_W: Code = "X5996";

// --- the validator: operands -------------------------------------------------
/// "Invalid src mod for first source param" (`!` on a float source).
pub const SOURCE_MODIFIER: Code = "X5364";
/// "aL can only be referenced … inside a loop/endloop block, or … in a
/// subroutine".
pub const AL_OUTSIDE_LOOP: Code = "X5370";
/// "First source parameter for texld* must be temp (r#), input (v#) or
/// constant (c#) register".
pub const TEXLD_COORDINATE: Code = "X5525";
/// "Second source parameter for texld* must be sampler stage (s#)".
pub const TEXLD_SAMPLER: Code = "X5528";
/// "Source modifier not allowed on sampler (s#) parameter to texld*".
pub const SAMPLER_SOURCE_MODIFIER: Code = "X5559";
/// "Negate or abs modifiers not permitted on source parameters to texld*".
pub const TEXLD_SOURCE_MODIFIER: Code = "X5561";
/// "Invalid register type for destination param".
pub const DESTINATION: Code = "X5578";
/// "The only instruction allowed to write to the predicate register is
/// setp".
pub const PREDICATE_WRITE: Code = "X5373";
/// "oDepth may not be written by the texkill instruction".
pub const TEXKILL_DEPTH: Code = "X5758";
/// "Third and fourth parameters to texldd must be temp (r#), input (v#) or
/// constant (c#) register".
pub const TEXLDD_GRADIENT: Code = "X5526";
/// "loop requires first parameter to be loop counter (aL)".
pub const LOOP_COUNTER: Code = "X5514";
/// "if requires parameter (the branch condition) to be boolean constant
/// register (b#), or predicate register (p0)".
pub const IF_CONDITION: Code = "X5917";
/// "breakp requires parameter to be predicate register (p0)".
pub const BREAKP_CONDITION: Code = "X5930";
/// "Dest writemask for SINCOS must be .xy, .x or .y".
pub const SINCOS_MASK: Code = "X5580";
/// "N different input registers (v*#) read by instruction".
pub const INPUT_PORTS: Code = "X5583";
/// "N different constant registers (c#) read by instruction".
pub const CONST_PORTS: Code = "X5584";
/// "Src and dest registers for NRM cannot be the same".
pub const NRM_ALIAS: Code = "X5604";
/// "rep instruction cannot be predicated" (and other flow control).
pub const PREDICATED_FLOW: Code = "X5665";
/// "Invalid reg type for first source param".
pub const SOURCE_REGISTER: Code = "X5679";
/// [`SOURCE_REGISTER`] in vs_2_0 and vs_2_x (`mov r0, a0`).
pub const SOURCE_REGISTER_VS: Code = "X5680";
/// [`SOURCE_REGISTER`] in vs_3_0.
pub const SOURCE_REGISTER_VS_3_0: Code = "X5681";
/// "Reg num … on matrix instruction causes attempt to access out of range
/// register".
pub const MATRIX_RANGE: Code = "X5684";
/// "Cannot use negate or abs on second source parameter to vector*matrix".
pub const MATRIX_MODIFIER: Code = "X5689";
/// "The setp instruction must write to the predicate register".
pub const SETP_DESTINATION: Code = "X5714";
/// "Dest writemask for NRM must be .xyzw (default) or .xyz".
pub const NRM_MASK: Code = "X5530";
/// "Cannot use negate or abs on source parameter(s) to dsx instruction"
/// (and dsy).
pub const GRADIENT_MODIFIER: Code = "X5690";
/// "oDepth may not be written by the … instruction".
pub const DEPTH_WRITER: Code = "X5758";
/// "When writing to oDepth, … instruction must use replicate swizzle on
/// source parameter(s)".
pub const DEPTH_REPLICATE: Code = "X6062";
/// "Invalid parameter count" (a predicate on `nop`).
pub const PARAMETER_COUNT: Code = "X5521";
/// "Dest register for CRS cannot be the same as a source register".
pub const CRS_ALIAS: Code = "X5761";
/// "Swizzle not permitted on source paramters to CRS".
pub const CRS_SWIZZLE: Code = "X5762";
/// "Write mask for CRS must be one of …".
pub const CRS_MASK: Code = "X5763";
/// "Dest register for POW cannot be the same as second source register".
pub const POW_ALIAS: Code = "X5764";
/// "… requires replicate swizzle for source parameter(s)".
pub const REPLICATE: Code = "X5793";
/// "Predicate register (p0) parameter to if instruction must specify
/// replicate swizzle".
pub const PREDICATE_REPLICATE: Code = "X5949";
/// "When predicate register is used as the condition for a callnz
/// instruction, a replicate swizzle must be specified".
pub const CALLNZ_REPLICATE: Code = "X5946";
/// "source modifiers are not allowed on predicates".
pub const PREDICATE_MODIFIER: Code = "X2019";
/// "Cannot use negate or abs on source parameter(s) to if instruction".
pub const IF_MODIFIER: Code = "X5690";
/// "Source predicate p0 must use one of the following swizzles: .x | .y |
/// .z | .w | .xyzw".
pub const PREDICATE_SWIZZLE: Code = "X5667";
/// "vFace register can only be used as one of the sources to if_(cond),
/// break_(cond), setp_(cond), or the condition in a cmp".
pub const VFACE_USE: Code = "X5692";
/// "Third source parameter for dp2add must use a replicate swizzle".
pub const DP2ADD_REPLICATE: Code = "X5961";
/// "_sat not permitted on tex* instructions".
pub const SAT_TEXTURE: Code = "X5911";
/// "_sat not permitted with frc instruction".
pub const SAT_FRC: Code = "X5912";
/// "_sat not permitted with setp instruction".
pub const SAT_SETP: Code = "X6066";
/// "_sat not permitted with SINCOS instruction".
pub const SAT_SINCOS: Code = "X6061";
/// "callnz requires second source parameter … to be … b#, or predicate".
pub const CALLNZ_CONDITION: Code = "X5916";
/// "rep requires first parameter to be integer constant register (i#)".
pub const REP_OPERAND: Code = "X5932";
/// "M#x# instruction must use destination writemask".
pub const MATRIX_MASK: Code = "X6014";
/// "Dest register cannot be the same as first source register for m*x*".
pub const MATRIX_ALIAS: Code = "X6015";
/// "Dest register for m*x* … cannot be the same as one of the additional
/// registers implied by the matrix".
pub const MATRIX_ROWS_ALIAS: Code = "X6016";
/// "When constant registers are read multiple times in a single
/// instruction, the _abs modifier must either be on all or none".
pub const ABS_MIXED_IN_INSTRUCTION: Code = "X6045";
/// "texld/texldb/texldp/dsx/dsy instructions with r# as source cannot be
/// used inside dynamic conditional 'if' blocks, dynamic conditional
/// subroutine calls, or loop/rep with break*". ps30 reports it as a warning
/// while measuring and running a shader, and as this error when it writes
/// bytecode or under `--strict`.
pub const GRADIENT_IN_FLOW: Code = "X6077";
/// "Dest for SINCOS must be a temp (r#) register".
pub const SINCOS_DESTINATION: Code = "X6075";

// --- the validator: structure --------------------------------------------------
/// "'endloop' instruction does not match up to an 'loop'".
pub const ENDLOOP_MISMATCH: Code = "X5494";
/// "'label' is only permitted directly after a 'ret' instruction".
pub const LABEL_PLACE: Code = "X5813";
/// "Subroutine label number: # already defined earlier".
pub const LABEL_TWICE: Code = "X5821";
/// "Cannot call subroutine label defined earlier in shader" (what a
/// recursive call is refused with: calls must go forward).
pub const CALL_BACKWARD: Code = "X5824";
/// "Depth of loop nesting exceeds limit of 4".
pub const LOOP_DEPTH: Code = "X5827";
/// "'ret' instruction not permitted from inside any flow control block".
pub const RET_IN_BLOCK: Code = "X5833";
/// "'endrep' instruction does not match up to a 'rep'".
pub const ENDREP_MISMATCH: Code = "X5837";
/// "'endif' instruction does not match up to an 'if' or 'else'".
pub const ENDIF_MISMATCH: Code = "X5840";
/// "Depth of subroutine call nesting exceeds limit of 4".
pub const CALL_DEPTH: Code = "X5851";
/// "Depth of static 'if' nesting exceeds limit of 24".
pub const STATIC_IF_DEPTH: Code = "X5856";
/// "Depth of dynamic 'if' nesting exceeds limit of 24" for `if p0.c`.
pub const PREDICATE_IF_DEPTH: Code = "X5854";
/// "Depth of dynamic 'if' nesting exceeds limit of 24".
pub const DYNAMIC_IF_DEPTH: Code = "X5858";
/// "A 'ret' instruction must be followed by either (1) the end of the
/// shader or (2) a 'label' instruction".
pub const AFTER_RET: Code = "X5881";
/// "Subroutine with label #N called, but never defined".
pub const UNDEFINED_LABEL: Code = "X5884";
/// "Subroutine label #N never referenced".
pub const UNREFERENCED_LABEL: Code = "X5887";
/// "End of shader reached without 'ret' to terminate subroutine".
pub const SUBROUTINE_WITHOUT_RET: Code = "X5890";
/// "'else' instruction does not match up to an 'if'".
pub const ELSE_MISMATCH: Code = "X5895";
/// "'else' already used for current 'if' construct".
pub const ELSE_TWICE: Code = "X5896";
/// "'break' instruction not within a local loop/rep construct".
pub const BREAK_OUTSIDE: Code = "X5897";
/// "End of shader reached and 'loop'/'rep' construct was not completed".
pub const LOOP_UNCLOSED: Code = "X5905";
/// "End of shader reached and 'if' construct was not completed".
pub const IF_UNCLOSED: Code = "X5906";
/// "Too many (N) standard (non tex*) instruction slots used. Max. allowed
/// is M." (ps_2_0: 64; ps_2_x: its slot count).
pub const ARITHMETIC_SLOTS: Code = "X5234";
/// "Too many (N) tex* instruction slots used. Max. allowed is 32." (ps_2_0).
pub const TEXTURE_SLOTS: Code = "X5607";
/// "Too many (N) total instruction slots used. Max. allowed is M." (ps_2_0,
/// ps_2_x).
pub const TOTAL_SLOTS: Code = "X5617";
/// "Number of instruction slots used too high: N. Max. allowed is M."
/// (vs_2_0, vs_2_x).
pub const VERTEX_SLOTS: Code = "X5755";
/// "Too may static flow control instructions (N) for this shader model.
/// Maximum allowed is 16." (vs_2_0, vs_2_x; `D3DAssemble` returns E_FAIL).
pub const STATIC_FLOW_COUNT: Code = "X5520";
/// ps_2_0's and ps_2_x's "(Second source param) Register number: N on this
/// parameter for a matrix instruction causes attempt to access out of range
/// register" (ps_3_0's is X5684).
pub const PS2_MATRIX_RANGE: Code = "X5565";
/// vs_2_0's and vs_2_x's matrix rows past the file (ps_3_0's is X5684).
pub const VS2_MATRIX_RANGE: Code = "X5362";
/// vs_3_0's matrix rows past the file (ps_3_0's is X5684).
pub const VS3_MATRIX_RANGE: Code = "X5688";
/// ps_2_0's and ps_2_x's "2 different constant registers (c#) read by
/// instruction" (ps_3_0's is X5584).
pub const PS2_CONST_PORTS: Code = "X5213";
/// vs_2_0's and vs_2_x's two different constants in one instruction.
pub const VS2_CONST_PORTS: Code = "X5393";
/// vs_3_0's two different constants in one instruction.
pub const VS3_CONST_PORTS: Code = "X5752";
/// "Dependent tex-op sequence too long (4th order)" (ps_2_0).
pub const DEPENDENT_READS: Code = "X5775";
/// "Instruction not supported by version ps_2_0 pixel shader."
pub const PS_UNSUPPORTED: Code = "X5190";
/// "Source swizzles not allowed on tex* instruction." (ps_2_0, ps_2_x).
pub const TEX_SOURCE_SWIZZLE: Code = "X5198";
/// "Invalid source selector … The only available source swizzles in this
/// shader version are …" (ps_2_0; ps_2_x without arbitrary swizzles).
pub const PS2_SWIZZLE: Code = "X5202";
/// ps_2_x's "Depth of loop nesting exceeds limit of 4" (ps_3_0's is X5827).
pub const PS2X_LOOP_DEPTH: Code = "X5493";
/// ps_2_x's "Depth of subroutine call nesting exceeds limit of 4".
pub const PS2X_CALL_DEPTH: Code = "X5843";
/// ps_2_x's "Depth of dynamic 'if' nesting exceeds limit of 24" for `if p0.c`.
pub const PS2X_PREDICATE_IF_DEPTH: Code = "X5846";
/// ps_2_x's "Depth of static 'if' nesting exceeds limit of 24".
pub const PS2X_STATIC_IF_DEPTH: Code = "X5847";
/// ps_2_x's "Depth of dynamic 'if' nesting exceeds limit of 24".
pub const PS2X_DYNAMIC_IF_DEPTH: Code = "X5849";
/// "Instruction not supported by version vs_2_0 shader."
pub const VS_UNSUPPORTED: Code = "X5655";
/// "Second and third source params for SGN must both be different temp
/// (r#) registers." (vs_2_0, vs_2_x).
pub const SGN_SCRATCH: Code = "X5470";
/// The same rule in vs_3_0.
pub const SGN_SCRATCH_3_0: Code = "X5797";
/// "When a ps_2_0 shader writes to oCn, it must write to all of oC(n-1)
/// down to oC0 (no gaps)."
pub const COLOUR_OUTPUT_GAP: Code = "X5573";
/// "aL can only be referenced … inside a loop/endloop block" in the vertex
/// profiles (ps_3_0's is [`AL_OUTSIDE_LOOP`]).
pub const AL_OUTSIDE_LOOP_VS: Code = "X5705";
/// "Relative address must specify a single component selector (.x, .y, .z
/// or .w)": `c[a0 + 3]`, `c[a0.xy]`.
pub const RELATIVE_COMPONENT: Code = "X5804";
/// "Relative address for input (v#) can only be aL register" (vs_3_0).
pub const INPUT_RELATIVE_AL: Code = "X5964";
/// "Relative addressing of o# register requires aL register" (vs_3_0).
pub const OUTPUT_RELATIVE_AL: Code = "X5728";
/// "Different relative addressing of constant registers cannot be combined
/// in one instruction" (`c[a0.x + 3]` beside `c[a0.x + 4]` or `c[aL]`).
pub const CONST_RELATIVE_DIFFERENT: Code = "X5743";
/// "Absolute and relative addressing of constant registers cannot be
/// combined in one instruction" (vs_2_0, vs_2_x).
pub const CONST_RELATIVE_ABSOLUTE: Code = "X5747";
/// The same rule in vs_3_0.
pub const CONST_RELATIVE_ABSOLUTE_3_0: Code = "X5749";
/// "mova instruction can only write to the address register".
pub const MOVA_DESTINATION: Code = "X5372";
/// [`MOVA_DESTINATION`] in vs_3_0.
pub const MOVA_DESTINATION_3_0: Code = "X5713";
/// [`CONST_RELATIVE_DIFFERENT`] in vs_3_0.
pub const CONST_RELATIVE_DIFFERENT_3_0: Code = "X5745";
/// [`AL_OUTSIDE_LOOP_VS`] in vs_3_0.
pub const AL_OUTSIDE_LOOP_VS_3_0: Code = "X5707";

// --- ps_1_x (core::ps1): the rules D3DAssemble holds ps_1_1–ps_1_4 to ------
// Where ps_1_4 words a rule of its own, its code is the second constant.
/// "complement cannot be used with other modifiers" (`1-r0_bias`).
pub const COMPLEMENT_WITH_MODIFIER: Code = "X2012";
/// "For ps_1_2 or ps_1_3, the cmp or dp4 instructions cannot have a source
/// register the same as the destination register."
pub const PS1_SOURCE_IS_DEST: Code = "X5024";
/// "Invalid src mod for … source param." (`_x2` before ps_1_4).
pub const PS1_SOURCE_MODIFIER: Code = "X5025";
/// "Src selector .b … is only valid for instructions that occur in the
/// alpha pipe."
pub const PS1_BLUE_SELECTOR: Code = "X5026";
/// "Invalid src swizzle for … source param." (ps_1_1–ps_1_3).
pub const PS1_SWIZZLE: Code = "X5027";
/// "Texture register result of texkill, texm3x2depth or texm*pad
/// instructions must not be read."
pub const PS1_PAD_READ: Code = "X5031";
/// "Read of uninitialized components(*) in …" (ps_1_1–ps_1_3).
pub const PS1_UNINITIALIZED: Code = "X5036";
/// "Invalid reg type for dest param." (ps_1_1–ps_1_3).
pub const PS1_DEST_TYPE: Code = "X5037";
/// "Invalid dst shift." (`_x8`, `_d4`, `_d8` before ps_1_4).
pub const PS1_SHIFT: Code = "X5045";
/// "Dest write mask must be .rgb, .a, or .rgba (all)." (ps_1_1–ps_1_3).
pub const PS1_MASK: Code = "X5046";
/// "Tex register t# already declared."
pub const PS1_TEX_TWICE: Code = "X5053";
/// "t# registers must appear in sequence."
pub const PS1_TEX_ORDER: Code = "X5054";
/// "Cannot use tex* instruction after non-tex* instruction."
pub const PS1_TEX_AFTER_ARITHMETIC: Code = "X5055";
/// "Incomplete texm* sequence."
pub const PS1_TEXM_INCOMPLETE: Code = "X5056";
/// "First source for cnd instruction must be 'r0.a'."
pub const PS1_CND_SOURCE: Code = "X5059";
/// "Const declaration (def) must appear before other instructions."
pub const PS1_DEF_LATE: Code = "X5063";
/// ps_1_4's wording of [`PS1_DEF_LATE`].
pub const PS14_DEF_LATE: Code = "X5155";
/// "Dest write mask must be .rgb, or .rgba (all) for dp3."
pub const PS1_DP3_MASK: Code = "X5066";
/// "Cannot set co-issue ('+') on consecutive instructions."
pub const PS1_COISSUE_CHAIN: Code = "X5070";
/// ps_1_4's wording of [`PS1_COISSUE_CHAIN`].
pub const PS14_COISSUE_CHAIN: Code = "X5161";
/// "(previous instruction) nop instruction cannot be co-issued."
pub const PS1_COISSUE_NOP: Code = "X5071";
/// ps_1_4's wording of [`PS1_COISSUE_NOP`].
pub const PS14_COISSUE_NOP: Code = "X5164";
/// "(previous instruction) Co-issued instruction cannot write all
/// components - must write either alpha or color."
pub const PS1_COISSUE_FIRST_ALL: Code = "X5080";
/// The same of the co-issued instruction itself.
pub const PS1_COISSUE_ALL: Code = "X5081";
/// "Co-issued instructions cannot both write to the same components of a
/// register."
pub const PS1_COISSUE_SAME: Code = "X5082";
/// "Co-issued instructions cannot both write to color components."
pub const PS1_COISSUE_COLOUR: Code = "X5083";
/// "Co-issued instructions cannot both write to alpha component."
pub const PS1_COISSUE_ALPHA: Code = "X5084";
/// ps_1_4: "(previous instruction) Individual instruction in co-issue pair
/// cannot write both alpha and color component(s)."
pub const PS14_COISSUE_FIRST_BOTH: Code = "X5172";
/// ps_1_4: the same of the co-issued instruction itself.
pub const PS14_COISSUE_BOTH: Code = "X5173";
/// ps_1_4: "Co-issued instructions cannot both write to the same
/// component(s)."
pub const PS14_COISSUE_SAME: Code = "X5174";
/// ps_1_4: "One of the instructions in a co-issue pair must write to alpha
/// only (.a writemask)."
pub const PS14_COISSUE_ALPHA: Code = "X5175";
/// "Too many arithmetic instruction slots used: N. Max. allowed (counting
/// any co-issued pairs as 1) is 8." (ps_1_1–ps_1_3).
pub const PS1_ARITHMETIC_SLOTS: Code = "X5088";
/// "r0 must be written by shader." (ps_1_1–ps_1_3).
pub const PS1_R0_UNWRITTEN: Code = "X5090";
/// ps_1_4's wording of [`PS1_R0_UNWRITTEN`].
pub const PS14_R0_UNWRITTEN: Code = "X5185";
/// ps_1_4: "Modifiers are not allowed on constants for ps_1_4."
pub const PS14_CONST_MODIFIER: Code = "X5097";
/// ps_1_1–ps_1_3: "Modifiers are not allowed on constants for ps_1_x."
pub const PS1_CONST_MODIFIER: Code = "X5539";
/// ps_1_4: "Source register type must be texture coordinate input (t#) for
/// texcrd instruction."
pub const PS14_TEXCRD_SOURCE: Code = "X5098";
/// ps_1_4: "_dz(=_db) modifier on source param for texld only allowed if
/// source is a temp register (r#)."
pub const PS14_DZ_ON_TEXCOORD: Code = "X5101";
/// ps_1_4: "_dz(=_db) modifier … must be paired with source selector
/// .xyz(=.rgb)."
pub const PS14_DZ_SELECTOR: Code = "X5102";
/// ps_1_4: "Using a texture coordinate register (t#) as source for texld
/// requires component selector .xyw(=.rga), or .xyz(=.rgb)."
pub const PS14_TEXCOORD_SELECTOR: Code = "X5108";
/// ps_1_4: "Using a temp register (r#) as source for texld requires
/// component selector .xyz(==.rgb)."
pub const PS14_TEMP_SELECTOR: Code = "X5109";
/// ps_1_4: "Texture coordinate registers (t#) are not available to
/// arithmetic instructions."
pub const PS14_TEXCOORD_IN_ARITHMETIC: Code = "X5112";
/// ps_1_4: "Invalid source selector."
pub const PS14_SELECTOR: Code = "X5116";
/// ps_1_4: "Read of uninitialized component(*) in r#" after the phase
/// marker, whose alpha the marker lost.
pub const PS14_ALPHA_AFTER_PHASE: Code = "X5119";
/// ps_1_4: "Read of uninitialized components(*) in …".
pub const PS14_UNINITIALIZED: Code = "X5121";
/// ps_1_4: "Invalid register type for destination param."
pub const PS14_DEST_TYPE: Code = "X5123";
/// ps_1_4: "texcrd with _dw(=_da) source modifier must use .xy(=.rg)
/// destination writemask."
pub const PS14_TEXCRD_DW_MASK: Code = "X5125";
/// ps_1_4: "texcrd must use .xyz(=.rgb) destination writemask."
pub const PS14_TEXCRD_MASK: Code = "X5126";
/// ps_1_4: "Register r# (and thus texture stage #) already used as a
/// destination for a tex* instruction in this block of the shader."
pub const PS14_TEX_TWICE: Code = "X5140";
/// ps_1_4: "tex* instructions cannot be after arithmetic instructions
/// within one phase."
pub const PS14_TEX_AFTER_ARITHMETIC: Code = "X5141";
/// ps_1_4: "Multiple phase markers not permitted."
pub const PS14_PHASE_TWICE: Code = "X5142";
/// ps_1_4: "Earlier texld instruction used _dz(=_db) … When a phase marker
/// is present, the _dz modifier is only permitted after the phase marker."
pub const PS14_DZ_BEFORE_PHASE: Code = "X5143";
/// ps_1_4: "v# register read by instruction(s) before phase marker."
pub const PS14_COLOUR_BEFORE_PHASE: Code = "X5144";
/// ps_1_4: "When a phase marker is present in a shader, texkill is only
/// permitted after the phase marker."
pub const PS14_TEXKILL_BEFORE_PHASE: Code = "X5145";
/// ps_1_4: "bem can only be used before a phase marker (required) later in
/// the shader."
pub const PS14_BEM_PLACE: Code = "X5147";
/// ps_1_4: "Writemask for bem must be '.rg'".
pub const PS14_BEM_MASK: Code = "X5148";
/// ps_1_4: "When a phase marker is present in a shader, texdepth is only
/// permitted after the phase marker."
pub const PS14_TEXDEPTH_BEFORE_PHASE: Code = "X5154";
/// ps_1_4: "Too many (N) tex* instruction slots used before phase marker.
/// Max. allowed in a phase is 6."
pub const PS14_TEXTURE_SLOTS_PHASE1: Code = "X5176";
/// ps_1_4: "… tex* instruction slots used after phase marker."
pub const PS14_TEXTURE_SLOTS_PHASE2: Code = "X5178";
/// ps_1_4: "… arithmetic instruction slots used after phase marker."
pub const PS14_ARITHMETIC_SLOTS_PHASE2: Code = "X5179";
/// ps_1_4 without a phase marker: "Too many (N) tex* instruction slots
/// used. Max. allowed is 6."
pub const PS14_TEXTURE_SLOTS: Code = "X5180";
/// ps_1_4 without a phase marker: "Too many (N) arithmetic instruction
/// slots used. Max. allowed … is 8."
pub const PS14_ARITHMETIC_SLOTS: Code = "X5181";
/// ps_1_4: "… arithmetic instruction slots used before phase marker."
pub const PS14_ARITHMETIC_SLOTS_PHASE1: Code = "X5486";
/// "Instruction modifiers are not allowed for tex* instructions." (`_sat`
/// on a texture instruction before ps_1_4).
pub const PS1_TEX_MODIFIER: Code = "X5042";
/// "Dest shift not allowed for tex* instructions." (before ps_1_4).
pub const PS1_TEX_SHIFT: Code = "X5043";
/// ps_1_4's wording of [`PS1_TEX_MODIFIER`].
pub const PS14_TEX_MODIFIER: Code = "X5128";
/// ps_1_4's wording of [`PS1_TEX_SHIFT`].
pub const PS14_TEX_SHIFT: Code = "X5129";
