//! What `ps30 disasm --json` prints: the decoded stream — constant table,
//! comment blocks, instructions with their token and byte offsets — next
//! to the listing.

use crate::core::bytecode::listing::{instruction_text, slots, Listing};
use crate::core::bytecode::{ctab, ItemKind, Module, CTAB};
use crate::present::constants::table_json;
use serde_json::{json, Value};

/// The JSON form of a disassembly of `bytes` bytes.
pub fn disasm_json(name: &str, module: &Module, bytes: usize, listing: &Listing) -> Value {
    let (texture, arithmetic) = slots(module);
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
                "text": instruction_text(ins),
            })),
        }
    }
    json!({
        "file": name,
        "version": "ps_3_0",
        "tokens": bytes / 4,
        "bytes": bytes,
        "slots": {"total": texture + arithmetic, "texture": texture, "arithmetic": arithmetic},
        "constant_table": table.as_ref().map(table_json),
        "comments": comments,
        "instructions": instructions,
        "listing": listing.text,
    })
}
