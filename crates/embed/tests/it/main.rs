mod common;
mod embeddings;
mod sight;
