//! `phygap info`: the compute adapters found and which backend each `--backend` choice would use.

use anyhow::Result;

use phygap::core::config::BackendChoice;
use phygap::gpu::list_adapters;
use phygap::pipeline::backend::describe;

pub fn run() -> Result<()> {
    println!("phygap {}", env!("CARGO_PKG_VERSION"));
    if let Ok(v) = std::env::var("WGPU_BACKEND") {
        println!("WGPU_BACKEND={v}");
    }
    let adapters = list_adapters();
    if adapters.is_empty() {
        println!("gpu adapters: none (Vulkan, Metal or DX12)");
    } else {
        println!("gpu adapters:");
        for a in &adapters {
            let features: String = [
                (a.float_atomics, ", float atomics"),
                (a.subgroups, ", subgroups"),
            ]
            .iter()
            .filter(|(has, _)| *has)
            .map(|(_, name)| *name)
            .collect();
            println!("  {a}{features}");
        }
    }
    println!("backend choices:");
    for (choice, name) in [
        (BackendChoice::Auto, "auto"),
        (BackendChoice::Cpu, "cpu"),
        (BackendChoice::Fast, "fast"),
        (BackendChoice::Gpu, "gpu"),
    ] {
        match describe(choice) {
            Ok(what) => println!("  --backend {name:<4} → {what}"),
            Err(e) => println!("  --backend {name:<4} → error: {e}"),
        }
    }
    Ok(())
}
