//! The guide tells the truth: its instruction list (docs/assembly.md) is the
//! instruction table.

#[test]
fn the_guide_lists_the_instruction_table() {
    let page = include_str!("../docs/assembly.md");
    let table = ps30::core::isa::markdown_table();
    assert!(
        page.contains(&table),
        "docs/assembly.md's instruction list differs from src/core/isa.rs; replace it with:\n{table}"
    );
}
