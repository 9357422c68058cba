//! What `ps30 disasm --json` prints: the decoded stream — constant table,
//! comment blocks, instructions with their token and byte offsets — next
//! to both listings (Microsoft's text and ps30's annotated one).

use crate::core::bytecode::listing::{self, instruction_text};
use crate::core::bytecode::{ctab, microsoft, ItemKind, Module, CTAB};
use crate::present::constants::table_json;
use serde_json::{json, Value};

/// The JSON form of a disassembly of `bytes` bytes. `slots` is the count
/// of Microsoft's listing (its last line), `slots_documented` the count by
/// the per-instruction table of Microsoft's documentation.
pub fn disasm_json(name: &str, module: &Module, bytes: usize) -> Value {
    let (texture, arithmetic) = microsoft::slots(module);
    let (doc_texture, doc_arithmetic) = listing::slots(module);
    let table = module.items.iter().find_map(|i| match &i.kind {
        ItemKind::Comment(body) if body.first() == Some(&CTAB) => ctab::decode(&body[1..]).ok(),
        _ => None,
    });
    let mut comments = Vec::new();
    let mut instructions = Vec::new();
    for item in &module.items {
        match &item.kind {
            ItemKind::Comment(body) => comments.push(json!({
                "token": item.token,
                "byte": item.token * 4,
                "tokens": body.len(),
                "fourcc": body.first().map(|t| t.to_le_bytes()).filter(|b| b.iter().all(u8::is_ascii_alphanumeric)).map(|b| String::from_utf8_lossy(&b).into_owned()),
                "words": body.iter().map(|t| format!("{t:08x}")).collect::<Vec<_>>(),
            })),
            ItemKind::Instr(ins) => instructions.push(json!({
                "token": item.token,
                "byte": item.token * 4,
                "length": ins.operand_tokens(),
                "opcode": ins.op.info().mnemonic,
                "code": ins.op.info().code,
                "text": microsoft::instruction(ins),
                "annotated": instruction_text(ins),
            })),
        }
    }
    json!({
        "file": name,
        "version": "ps_3_0",
        "tokens": bytes / 4,
        "bytes": bytes,
        "slots": {"total": texture + arithmetic, "texture": texture, "arithmetic": arithmetic},
        "slots_documented": {"total": doc_texture + doc_arithmetic, "texture": doc_texture, "arithmetic": doc_arithmetic},
        "constant_table": table.as_ref().map(table_json),
        "comments": comments,
        "instructions": instructions,
        "listing": microsoft::listing(module),
        "annotated": listing::listing(module).text,
    })
}

/// The JSON form of a ps_1_x disassembly, in the shape of [`disasm_json`]:
/// no comment blocks or constant table (ps_1_x streams are read without
/// them), both listings Microsoft's text (it reads back), and the slots
/// ps_1_x counts under both tables.
pub fn ps1_json(name: &str, program: &crate::core::ps1::Program, bytes: usize) -> Value {
    use crate::core::ps1::{listing as ps1_listing, tokens};
    let slots = program.slots();
    let mut token = 1u32;
    let mut instructions = Vec::new();
    for i in &program.instrs {
        let length = i.dst.iter().count() + i.src.len() + if i.def.is_some() { 4 } else { 0 };
        let text = ps1_listing::instruction(i);
        instructions.push(json!({
            "token": token,
            "byte": token * 4,
            "length": length,
            "opcode": i.op.info().mnemonic,
            "code": i.op.info().code,
            "text": text,
            "annotated": text,
        }));
        token += 1 + length as u32;
    }
    let text = ps1_listing::listing(program);
    let count =
        json!({"total": slots.total(), "texture": slots.texture, "arithmetic": slots.arithmetic});
    json!({
        "file": name,
        "version": program.profile.name(),
        "tokens": tokens::encode(program).len().max(bytes / 4),
        "bytes": bytes,
        "slots": count,
        "slots_documented": count,
        "constant_table": null,
        "comments": [],
        "instructions": instructions,
        "listing": text,
        "annotated": text,
    })
}
