mod common;
mod crossing;
mod embeddings;
mod fan;
mod fast;
mod mutual;
mod sight;
mod witness;
