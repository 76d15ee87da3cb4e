mod common;
mod embeddings;
mod fan;
mod mutual;
mod sight;
mod witness;
