mod common;
mod crossing;
mod embeddings;
mod fan;
mod mutual;
mod sight;
mod witness;
