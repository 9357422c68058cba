//! `reports/` is reproducible: generating it twice — once on one emulator
//! thread, once on all cores — gives the same files, byte for byte, and the
//! pages link only to figures that exist.

use std::collections::BTreeMap;
use std::path::Path;

fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().to_string_lossy().into_owned();
                out.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    out
}

#[test]
fn two_runs_write_the_same_bytes() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let write = |dir: &Path, threads| {
        let mut batch = ps30::core::output::Batch::new(dir).unwrap();
        let g = ps30::present::report::generate(&mut batch, dir, threads, &|_, _, _| {}).unwrap();
        batch.commit().unwrap();
        g
    };
    let (ga, gb) = (write(a.path(), Some(1)), write(b.path(), None));
    assert!(ga.all_agree() && gb.all_agree());
    assert_eq!(ga.files, gb.files);
    let (fa, fb) = (files(a.path()), files(b.path()));
    assert_eq!(fa.keys().collect::<Vec<_>>(), fb.keys().collect::<Vec<_>>());
    for (name, bytes) in &fa {
        assert!(bytes == &fb[name], "{name} differs between runs");
    }
    // Every file generate reports is there, and nothing else.
    let mut listed: Vec<&String> = ga.files.iter().collect();
    listed.sort();
    assert_eq!(fa.keys().collect::<Vec<_>>(), listed);
    // Every figure a page links to exists; every figure is linked.
    let pages: String = fa
        .iter()
        .filter(|(n, _)| n.ends_with(".md"))
        .map(|(_, b)| String::from_utf8(b.clone()).unwrap())
        .collect();
    for name in fa.keys().filter(|n| n.ends_with(".png")) {
        assert!(pages.contains(&format!("({name})")), "{name} is not shown");
    }
    for link in pages.split("](figures/").skip(1) {
        let file = &link[..link.find(')').unwrap()];
        if file.is_empty() {
            continue; // the link to the folder itself
        }
        assert!(fa.contains_key(&format!("figures/{file}")), "{file}");
    }
    // Previews stay small.
    let total: usize = fa.values().map(Vec::len).sum();
    assert!(total < 4 << 20, "{total} bytes");
    for row in &ga.tonemap {
        assert!(row.preview_size.0 <= ps30::present::report::PREVIEW_WIDTH);
    }
}
