//! The README tells the truth: its instruction list is the instruction table.

#[test]
fn readme_lists_the_instruction_table() {
    let readme = include_str!("../README.md");
    let table = ps30::core::isa::markdown_table();
    assert!(
        readme.contains(&table),
        "README.md's instruction list differs from src/core/isa.rs; replace it with:\n{table}"
    );
}
