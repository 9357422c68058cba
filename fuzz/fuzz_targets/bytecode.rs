//! Any bytes through the bytecode reader. A refusal must name a byte inside
//! the input; a stream that reads must be written back byte for byte
//! directly, and through the listing every command parses as Microsoft's
//! assembler would write that listing (`sub` as `add`), and must go
//! through the rest of the front end (validation, the cost model) like any
//! source. Nothing may panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use ps30::core::bytecode::{listing, read, write, ItemKind};
use ps30::core::isa::Opcode;
use ps30::core::cost::{analyse, Environment, Profile};
use ps30::core::front::{parse, repeat};
use ps30::core::load::{self, Options};

fuzz_target!(|data: &[u8]| {
    let module = match read::read(data, 4_096) {
        Ok(m) => m,
        Err(e) => {
            assert!(e.byte <= data.len(), "{e} for {} bytes", data.len());
            return;
        }
    };
    assert_eq!(write::to_bytes(&write::encode(&module)), data);
    let text = listing::listing(&module).text;
    let (stmts, diags) = parse::parse(&text);
    assert!(!diags.has_errors(), "the listing does not parse:\n{text}");
    let expanded = repeat::expand(&stmts, &Default::default(), 1 << 20).expect("no macros");
    let again = write::assemble(&stmts, &expanded).expect("the listing writes");
    // Through text, `sub` is written as Microsoft's assembler writes it.
    let mut spelled = module.clone();
    for item in &mut spelled.items {
        if let ItemKind::Instr(i) = &mut item.kind {
            if i.op == Opcode::Sub {
                write::sub_as_add(i);
            }
        }
    }
    let expected = write::to_bytes(&write::encode(&spelled));
    assert_eq!(write::to_bytes(&write::encode(&again)), expected, "{text}");
    let options = Options {
        max_expanded: 4_096,
        ..Options::default()
    };
    let file = load::source_file("fuzz.fxo", data.to_vec(), &options).expect("it read once");
    if let Ok(loaded) = load::load(file, &options) {
        if let Ok(a) = analyse(
            &loaded.shader,
            &loaded.file,
            &Environment::default(),
            &Profile::ps_3_0(),
        ) {
            assert!(a.executed.min <= a.executed.max);
        }
    }
});
